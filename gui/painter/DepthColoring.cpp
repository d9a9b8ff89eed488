#include "DepthColoring.h"

#include <vtkActor.h>
#include <vtkAdaptiveSubdivisionFilter.h>
#include <vtkCleanPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkTriangleFilter.h>

#include <limits>

#include "VtkGeometry.h"
#include "viewpipe/report/style.hpp"

namespace viewpipe::gui {

vtkSmartPointer<vtkPolyData> depthLevels(const std::shared_ptr<const PolygonMesh>& faces, const Pipeline<double>& pipeline,
                                         const DepthOptions& options)
{
    // Only the points of these faces: the others must not widen the bands' range.
    auto used = vtkSmartPointer<vtkCleanPolyData>::New();
    used->SetInputData(facesData(faces, Coordinates::Exact)); // depths from the exact vertices
    used->PointMergingOff();
    used->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    auto data = vtkSmartPointer<vtkPolyData>::New();
    if (faces->faces.size() > 50000) {
        used->Update();
        data->ShallowCopy(used->GetOutput());
    } else {
        auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
        triangles->SetInputConnection(used->GetOutputPort());
        triangles->Update();
        auto fine = vtkSmartPointer<vtkAdaptiveSubdivisionFilter>::New();
        fine->SetInputConnection(triangles->GetOutputPort());
        fine->SetMaximumEdgeLength(triangles->GetOutput()->GetLength() / 32);
        fine->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        fine->Update();
        data->ShallowCopy(fine->GetOutput());
    }
    auto levels = vtkSmartPointer<vtkDoubleArray>::New();
    levels->SetName("depth level");
    const Mat4<double> clip = pipeline.clipMatrix();
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
        const double* p = data->GetPoint(i);
        levels->InsertNextValue(depthLevelAt(clip, pipeline.clipVolume, Vec3<double>(p[0], p[1], p[2]), options)
                                    .value_or(std::numeric_limits<double>::quiet_NaN()));
    }
    data->GetPointData()->SetScalars(levels);
    return data;
}

vtkSmartPointer<vtkLookupTable> bandColors(const DepthBands& bands)
{
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(bands.count);
    table->SetTableRange(bands.first, bands.first + bands.count * bands.levelsPerBand);
    for (int k = 0; k < bands.count; ++k) {
        const report::Rgb c = report::bandColor(bands, k);
        table->SetTableValue(k, c.r, c.g, c.b, 1.0);
    }
    table->SetNanColor(report::kNoBandColor.r, report::kNoBandColor.g, report::kNoBandColor.b, report::kNoBandOpacity);
    return table;
}

void colorByLevels(vtkActor* actor, vtkLookupTable* table)
{
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOn();
    mapper->ScalarVisibilityOn();
}

} // namespace viewpipe::gui
