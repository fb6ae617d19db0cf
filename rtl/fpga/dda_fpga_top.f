// SPDX-License-Identifier: Apache-2.0
// The sources of the place-and-route wrapper (scripts/synth): the core's list and the
// wrapper. $(DDA_RTL) is the rtl/ folder, as in rtl/dda_core.f.
-f $(DDA_RTL)/dda_core.f
$(DDA_RTL)/fpga/dda_fpga_top.v
