// The scalar types the application uses are instantiated once, here.
#include "viewpipe/pipeline.hpp"

namespace viewpipe {

template Pipeline<float> buildPipeline(const CameraSpec<float>&);
template Pipeline<double> buildPipeline(const CameraSpec<double>&);
template Pipeline<long double> buildPipeline(const CameraSpec<long double>&);
template PointTrace<float> tracePoint(const Pipeline<float>&, const Vec3<float>&);
template PointTrace<double> tracePoint(const Pipeline<double>&, const Vec3<double>&);
template PointTrace<long double> tracePoint(const Pipeline<long double>&, const Vec3<long double>&);

} // namespace viewpipe
