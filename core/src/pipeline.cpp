// The projections' names, and the scalar types the application uses instantiated once, here.
#include "viewpipe/pipeline.hpp"

#include "viewpipe/exact.hpp"

namespace viewpipe {

std::string projectionName(ProjectionKind kind)
{
    switch (kind) {
    case ProjectionKind::Perspective: return "perspective";
    case ProjectionKind::Parallel: return "parallel";
    case ProjectionKind::Frustum: return "frustum";
    case ProjectionKind::Ortho: return "ortho";
    }
    return "";
}

template Pipeline<float> buildPipeline(const CameraSpec<float>&);
template Pipeline<double> buildPipeline(const CameraSpec<double>&);
template Pipeline<long double> buildPipeline(const CameraSpec<long double>&);
template PointTrace<float> tracePoint(const Pipeline<float>&, const Vec3<float>&);
template PointTrace<double> tracePoint(const Pipeline<double>&, const Vec3<double>&);
template PointTrace<long double> tracePoint(const Pipeline<long double>&, const Vec3<long double>&);
template Pipeline<Exact> buildPipeline(const CameraSpec<Exact>&);
template PointTrace<Exact> tracePoint(const Pipeline<Exact>&, const Vec3<Exact>&);

} // namespace viewpipe
