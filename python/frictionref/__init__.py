"""frictionref: the exact motion of a mass sliding with Coulomb friction.

The C++ library of the frictionref command, for Python (docs/python.md).
Each phase of the motion is solved in closed form and every stop, reversal
and breakaway is found exactly: no time step, no tolerance.

    >>> import frictionref
    >>> model = frictionref.Model(lambda_=0.7)          # m = B = w = 1, R = 0.7
    >>> table = frictionref.events(model, 30)           # one row per stick/slip phase
    >>> c = frictionref.curve(model, t_end=30, dt=0.01) # x, v, a, phase on a grid
    >>> frictionref.classify(model)['regime']
    'dead-bands'

Functions (each the command of the same name, with the same checks and the
same one-line messages, raised as ValueError; wrong types raise TypeError):

    Model(**keywords)        the model (the CLI's model options as keywords)
    events(model, t_end)     the phase table (numpy structured array)
    phases(model, t_end)     the phases one by one (or in chunks), flat memory
    summary(model, t_end)    counts and the final state, flat memory
    curve(model, t)          x, v, a, phase at any times; or on the CLI's grid
    classify(model)          the steady state (dict)
    stiff(model, t_end)      the stiff-spring (penalty) model
    compare(model, t, v)     another code's time history against the exact one
    sweep(...), map(...)     parameter studies on all cores, by shards
    newmark(records, ky)     Newmark's sliding block on ground-motion records
    distributed.map(client, ...)  a map on a Dask cluster, by shards

Messages name the parameter as the command line spells it ("--mass",
"--t-end"); the keyword is that name without the dashes, '-' read as '_'.
"""

from ._frictionref import (  # noqa: F401
    Model,
    Phase,
    PhaseStream,
    __version__,
    classify,
    compare,
    curve,
    events,
    map,
    newmark,
    phases,
    regime_threshold,
    stiff,
    summary,
    sweep,
)

__all__ = [
    "Model",
    "Phase",
    "PhaseStream",
    "classify",
    "compare",
    "curve",
    "events",
    "map",
    "newmark",
    "phases",
    "regime_threshold",
    "stiff",
    "summary",
    "sweep",
]


def __getattr__(name):
    # frictionref.distributed imports dask's distributed only when used.
    if name == "distributed":
        import importlib

        return importlib.import_module(".distributed", __name__)
    raise AttributeError(f"module 'frictionref' has no attribute {name!r}")
