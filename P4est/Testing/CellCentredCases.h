// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file CellCentredCases.h
/// The cases the cell-centred scheme's tests run end to end
/// (TestCellCentred.cxx alone, TestCellCentredRanks.cxx on several ranks).

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/ReconstructionPlan.h"

/// The chapter 5 circle (64 points) with the thesis's options and a circle
/// around it (5.3), three runs; run 1's cell is 2/64 ((5.10)-(5.11): L0 = 6).
inline sltk::Status planThesisCircle(sltk::ReconstructionPlan<2>& plan)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Runs = 3;
  options.Guess = sltk::InitialGuess::BoundingSphere;
  return sltk::planReconstruction(sltk::circleCloud(64), options, sltk::Context{}, plan);
}

/// The 642-point icosphere from a sphere around it, two runs on an octree
/// (levels 5 and 6 of a cube of edge 4 with run 1's cell 1/8).
inline sltk::Status planIcosphere(sltk::ReconstructionPlan<3>& plan)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Runs = 2;
  options.Guess = sltk::InitialGuess::BoundingSphere;
  return sltk::planReconstruction(sltk::icosphereCloud(3), options, sltk::Context{}, plan);
}
