// SPDX-License-Identifier: Apache-2.0
// The sources of the motion block behind its SPI bridge (dda_motion_spi top;
// docs/design.md "Bus bridges"). $(DDA_RTL) as in rtl/dda_core.f.
-f $(DDA_RTL)/dda_motion.f
$(DDA_RTL)/dda_spi.v
$(DDA_RTL)/dda_motion_spi.v
