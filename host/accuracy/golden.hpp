// SPDX-License-Identifier: Apache-2.0
// Golden reference model of the ellipse DDA: the single definition of behaviour.
//
// The umbrella header of its components, which depend on each other in one direction:
// datapath.hpp (the hardware's next-state function) <- runner.hpp (runs a plan's pieces)
// <- planner.hpp (cuts arcs into pieces; uses fixed_trig.hpp and geometry.hpp) <-
// accuracy.hpp (documented deviation bounds). core_model.hpp is the cycle-level model
// of the core's control around the same datapath.
#pragma once

#include "host/accuracy/accuracy.hpp"
#include "host/geometry/fixed_trig.hpp"
#include "host/geometry/geometry.hpp"
#include "host/planner/plan.hpp"
#include "host/planner/planner.hpp"
#include "host/runner/runner.hpp"
#include "model/datapath/datapath.hpp"
#include "model/datapath/errors.hpp"
