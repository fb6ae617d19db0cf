// SPDX-License-Identifier: Apache-2.0
// Golden reference model of the ellipse DDA: the single definition of behaviour.
//
// The umbrella header of its components, which depend on each other in one direction:
// datapath.hpp (the hardware's next-state function) <- runner.hpp (runs a plan's pieces)
// <- planner.hpp (cuts arcs into pieces; uses fixed_trig.hpp and geometry.hpp) <-
// accuracy.hpp (documented deviation bounds). core_model.hpp is the cycle-level model
// of the core's control around the same datapath.
#pragma once

#include "model/accuracy/accuracy.hpp"
#include "model/datapath/datapath.hpp"
#include "model/datapath/errors.hpp"
#include "model/geometry/fixed_trig.hpp"
#include "model/geometry/geometry.hpp"
#include "model/planner/plan.hpp"
#include "model/planner/planner.hpp"
#include "model/runner/runner.hpp"
