// SPDX-License-Identifier: Apache-2.0
// Types of the SystemC model, sized from the single source of widths (hw_params.hpp).
#pragma once

#include <systemc>

#include "model/datapath/hw_params.hpp"

namespace dda::sc {

using acc_t = sc_dt::sc_uint<hw::kAccWidth>;      // jv, jr, cap, corrections
using sum_t = sc_dt::sc_uint<hw::kAccWidth + 1>;  // jr + jv
using cnt_t = sc_dt::sc_uint<hw::kCntWidth>;
using cmd_t = sc_dt::sc_bv<hw::kCmdWidth>;

}  // namespace dda::sc
