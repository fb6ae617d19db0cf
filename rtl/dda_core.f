// SPDX-License-Identifier: Apache-2.0
// The sources of the dda_core top level: the one list every flow reads. Paths use
// $(DDA_RTL), the folder of this file (set it in the environment):
//   verilator -f rtl/dda_core.f ...     iverilog -c rtl/dda_core.f ...
// CMake reads it (cmake/dda_rtl.cmake); scripts/rtl-files.sh expands it for Yosys.
+incdir+$(DDA_RTL)
$(DDA_RTL)/dda_add.v
$(DDA_RTL)/dda_add3.v
$(DDA_RTL)/dda_add4.v
$(DDA_RTL)/dda_sum_zero.v
$(DDA_RTL)/dda_addsel.v
$(DDA_RTL)/dda_counter.v
$(DDA_RTL)/dda_integrator.v
$(DDA_RTL)/dda_linear.v
$(DDA_RTL)/dda_ctrl.v
$(DDA_RTL)/dda_core.v
