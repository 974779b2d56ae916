// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeSDF.h"

#include "vtkHyperTreeGrid.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkOctreeSDF);

vtkOctreeSDF::vtkOctreeSDF()
{
  this->OctreeStorageOn();
}

vtkHyperTreeGrid* vtkOctreeSDF::GetOutput()
{
  return vtkHyperTreeGrid::SafeDownCast(this->GetOutputDataObject(0));
}

vtkDataObject* vtkOctreeSDF::GetOutput(int port)
{
  return this->GetOutputDataObject(port);
}

int vtkOctreeSDF::RequestData(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  // A property: the same on every rank, so every rank stops here together.
  if (!this->GetOctreeStorage())
  {
    vtkErrorMacro("OctreeStorage is off: vtkOctreeSDF always stores the octree; turn OctreeStorage back on, or "
                  "use vtkSLLevelSetReconstruct for the uniform grids");
    return 0;
  }
  return this->Superclass::RequestData(request, inputs, outputs);
}
