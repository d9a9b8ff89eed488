// This file is compiled with -mfma: only called where the processor has FMA.
#include "viewpipe/double_double.hpp"

namespace viewpipe {

void transformPointsDoubleDoubleFma(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count)
{
    transformPointsDD(m, in, hi, lo, count);
}

} // namespace viewpipe
