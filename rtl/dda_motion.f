// SPDX-License-Identifier: Apache-2.0
// The sources of the motion block (dda_motion top: the core on a Wishbone bus, with its
// command queue; docs/design.md "Motion block"). $(DDA_RTL) as in rtl/dda_core.f.
-f $(DDA_RTL)/dda_core.f
$(DDA_RTL)/dda_stepdir.v
$(DDA_RTL)/dda_norm.v
$(DDA_RTL)/dda_pace.v
$(DDA_RTL)/dda_input.v
$(DDA_RTL)/dda_motion_io.v
$(DDA_RTL)/dda_motion.v
