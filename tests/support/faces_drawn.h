#pragma once

// What a renderer draws, counted: the faces of its visible actors' poly data
// (for the tests and benchmarks of level of detail).

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

inline vtkIdType facesDrawn(vtkRenderer* renderer)
{
    vtkIdType faces = 0;
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
        if (actor->GetVisibility())
            if (auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0)))
                faces += data->GetNumberOfPolys();
    return faces;
}
