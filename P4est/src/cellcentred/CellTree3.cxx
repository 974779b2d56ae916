// SPDX-License-Identifier: GPL-2.0-or-later
// CellTree<3>: CellTree.cxx compiled with p8est, p4est's own way of
// building its 3D code from the 2D source.
#include <p4est_to_p8est.h>

#include "CellTree.cxx"
