// Shows the C++ exception message that the Siconos Python binding drops when the
// event-driven scheme (EventDriven + LsodarOSI) is given our problem (README.md, "The
// Siconos event-driven scheme"). Not built by default (Siconos' headers take about a
// minute to compile); build it with -DPEERS_SICONOS_PROBE=ON and run it without arguments.
//
// Formulations, as in siconos_peer.py: "first-order" (relay on y = v), "lagrangian-relay"
// (relay on the velocity of a 1-DOF Lagrangian system), "contact-friction" (2-DOF, a
// permanent unilateral contact with 2-D Coulomb friction, NewtonImpactFrictionNSL).
#include <SiconosKernel.hpp>

#include <boost/exception/diagnostic_information.hpp>
#include <iostream>
#include <string>

namespace {

void probe(const std::string& formulation) {
  const double lambda = 0.7;
  std::cout << formulation << ": ";
  try {
    SP::NonSmoothDynamicalSystem nsds(new NonSmoothDynamicalSystem(0, 30));
    SP::OneStepNSProblem impact, acceleration;
    if (formulation == "first-order") {
      SP::SiconosVector x0(new SiconosVector(2));
      x0->zero();
      SP::SiconosMatrix A(new SimpleMatrix(2, 2));
      A->zero();
      (*A)(0, 1) = 1;
      SP::SiconosVector b(new SiconosVector(2));
      b->zero();
      SP::FirstOrderLinearTIDS ds(new FirstOrderLinearTIDS(x0, A, b));
      SP::SimpleMatrix C(new SimpleMatrix(1, 2));
      C->zero();
      (*C)(0, 1) = 1;
      SP::SimpleMatrix B(new SimpleMatrix(2, 1));
      B->zero();
      (*B)(1, 0) = lambda;
      SP::Interaction inter(new Interaction(SP::NonSmoothLaw(new RelayNSL(1, -1, 1)),
                                            SP::Relation(new FirstOrderLinearTIR(C, B))));
      nsds->insertDynamicalSystem(ds);
      nsds->link(inter, ds);
      impact.reset(new Relay());
      acceleration.reset(new Relay());
    } else if (formulation == "lagrangian-relay") {
      SP::SiconosVector q0(new SiconosVector(1)), v0(new SiconosVector(1));
      q0->zero();
      v0->zero();
      SP::SiconosMatrix M(new SimpleMatrix(1, 1));
      (*M)(0, 0) = 1;
      SP::LagrangianLinearTIDS ds(new LagrangianLinearTIDS(q0, v0, M));
      SP::SiconosVector f(new SiconosVector(1));
      f->zero();
      ds->setFExtPtr(f);
      SP::SimpleMatrix H(new SimpleMatrix(1, 1));
      (*H)(0, 0) = 1;
      SP::Interaction inter(new Interaction(SP::NonSmoothLaw(new RelayNSL(1, -lambda, lambda)),
                                            SP::Relation(new LagrangianLinearTIR(H))));
      nsds->insertDynamicalSystem(ds);
      nsds->link(inter, ds);
      impact.reset(new LCP());
      acceleration.reset(new LCP());
    } else {
      SP::SiconosVector q0(new SiconosVector(2)), v0(new SiconosVector(2));
      q0->zero();
      v0->zero();
      SP::SiconosMatrix M(new SimpleMatrix(2, 2));
      M->eye();
      SP::LagrangianLinearTIDS ds(new LagrangianLinearTIDS(q0, v0, M));
      SP::SiconosVector f(new SiconosVector(2));
      (*f)(0) = 0;
      (*f)(1) = -1;  // unit normal load
      ds->setFExtPtr(f);
      SP::SimpleMatrix H(new SimpleMatrix(2, 2));  // y = (gap z, tangential x)
      H->zero();
      (*H)(0, 1) = 1;
      (*H)(1, 0) = 1;
      SP::Interaction inter(
          new Interaction(SP::NonSmoothLaw(new NewtonImpactFrictionNSL(0.0, 0.0, lambda, 2)),
                          SP::Relation(new LagrangianLinearTIR(H))));
      nsds->insertDynamicalSystem(ds);
      nsds->link(inter, ds);
      impact.reset(new FrictionContact(2));
      acceleration.reset(new FrictionContact(2));
    }
    SP::TimeDiscretisation td(new TimeDiscretisation(0, 0.01));
    SP::EventDriven simulation(new EventDriven(nsds, td));
    simulation->insertIntegrator(SP::LsodarOSI(new LsodarOSI()));
    simulation->insertNonSmoothProblem(impact, SICONOS_OSNSP_ED_IMPACT);
    simulation->insertNonSmoothProblem(acceleration, SICONOS_OSNSP_ED_SMOOTH_ACC);
    simulation->initialize();
    int events = 0;
    while (simulation->hasNextEvent() && events < 20) {
      simulation->advanceToEvent();
      simulation->processEvents();
      ++events;
    }
    std::cout << "ran " << events << " events\n";
  } catch (...) {
    std::cout << "exception:\n" << boost::current_exception_diagnostic_information() << "\n";
  }
}

}  // namespace

int main() {
  for (const char* formulation : {"first-order", "lagrangian-relay", "contact-friction"})
    probe(formulation);
  return 0;
}
