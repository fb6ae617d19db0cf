// SPDX-License-Identifier: Apache-2.0
// Golden reference model of the ellipse DDA: the single definition of behaviour.
//
// The umbrella header of its components, which depend on each other in one direction:
// datapath.hpp (the hardware's next-state function) <- runner.hpp (runs a plan's pieces)
// <- planner.hpp (cuts arcs into pieces; uses fixed_trig.hpp and geometry.hpp) <-
// accuracy.hpp (documented deviation bounds). core_model.hpp is the cycle-level model
// of the core's control around the same datapath.
#pragma once

#include "accuracy/accuracy.hpp"
#include "datapath/datapath.hpp"
#include "datapath/errors.hpp"
#include "geometry/fixed_trig.hpp"
#include "geometry/geometry.hpp"
#include "planner/plan.hpp"
#include "planner/planner.hpp"
#include "runner/runner.hpp"
