// Everything public in one include.
#pragma once

#include "frictionref/classification.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/den_hartog.hpp"
#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/model.hpp"
#include "frictionref/model_fields.hpp"
#include "frictionref/parameter_map.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/sampling.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/stiff_spring.hpp"
#include "frictionref/sweep.hpp"
#include "frictionref/time_history.hpp"
#include "frictionref/types.hpp"
#include "frictionref/version.hpp"
