#include "viewpipe/double_double.hpp"

namespace viewpipe {

// Compiled with -mfma in double_double_fma.cpp.
void transformPointsDoubleDoubleFma(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count);

void transformPointsDoubleDouble(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count)
{
#if defined(__x86_64__) || defined(__i386__)
    static const bool fma = __builtin_cpu_supports("fma");
#else // WebAssembly: no FMA to ask for
    constexpr bool fma = false;
#endif
    if (fma)
        transformPointsDoubleDoubleFma(m, in, hi, lo, count);
    else
        transformPointsDD(m, in, hi, lo, count);
}

} // namespace viewpipe
