// SPDX-License-Identifier: Apache-2.0
// The sources of the board top for the iCE40-HX8K breakout board (docs/board.md): the
// block behind its SPI bridge and the top. $(DDA_RTL) as in rtl/dda_core.f.
-f $(DDA_RTL)/dda_motion_spi.f
$(DDA_RTL)/board/dda_hx8k_evn.v
