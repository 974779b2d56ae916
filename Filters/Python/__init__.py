"""SLTK, the Semi-Lagrangian level-set ToolKit: VTK filters.

    from sltk import vtkSLLevelSetReconstruct, vtkCWENOHJBSolver, vtkOctreeSDF

Import from pvpython, pvbatch, or /usr/bin/python3 (ParaView's VTK).
"""
from .SLTKFilters import *  # noqa: F401,F403
