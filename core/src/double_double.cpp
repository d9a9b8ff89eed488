#include "viewpipe/double_double.hpp"

namespace viewpipe {

// Compiled with -mfma in double_double_fma.cpp.
void transformPointsDoubleDoubleFma(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count);

void transformPointsDoubleDouble(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count)
{
    static const bool fma = __builtin_cpu_supports("fma");
    if (fma)
        transformPointsDoubleDoubleFma(m, in, hi, lo, count);
    else
        transformPointsDD(m, in, hi, lo, count);
}

} // namespace viewpipe
