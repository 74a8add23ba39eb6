// Marks a simulation as busy (stepping or rendering) while Python's lock is released for it, so that other threads
// are refused its use meanwhile (Simulation::check_idle). Made and destroyed with the lock held: declare it before
// the pybind11::gil_scoped_release, so that the lock is back when it clears the mark.
#pragma once

#include "simulation.hpp"

namespace softbody_python {

class SteppingMark {
 public:
  explicit SteppingMark(Simulation& simulation) : simulation_(simulation) { simulation_.set_stepping(true); }
  ~SteppingMark() { simulation_.set_stepping(false); }
  SteppingMark(const SteppingMark&) = delete;
  SteppingMark& operator=(const SteppingMark&) = delete;

 private:
  Simulation& simulation_;
};

}  // namespace softbody_python
