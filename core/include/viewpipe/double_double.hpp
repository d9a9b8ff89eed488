#pragma once

// Double-double (about 106 bits) for the one hot loop where width costs most:
// pushing vertices through the normalizing matrix. A value is hi + lo with
// |lo| <= ulp(hi)/2; sums and products are compensated with the error-free
// transformations TwoSum and TwoProd (fused multiply-add where the compiler
// targets it, Dekker's splitting otherwise), which is several times cheaper than software binary128 or MPFR. Errors are
// a few units of 2^-104, not a correctly rounded result.

#include <array>
#include <cmath>

#include "viewpipe/linalg.hpp"

namespace viewpipe {

struct DoubleDouble {
    double hi = 0, lo = 0;
};

// The matrix held as double-double entries.
struct Mat4DD {
    DoubleDouble m[4][4];
};

// The kernels are compiled twice, with and without hardware FMA (see
// transformPointsDoubleDouble); distinct namespaces keep the two apart.
#ifdef __FMA__
inline namespace with_fma {
#else
inline namespace without_fma {
#endif

inline DoubleDouble twoSum(double a, double b)
{
    const double s = a + b;
    const double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

inline DoubleDouble quickTwoSum(double a, double b)
{
    const double s = a + b;
    return {s, b - (s - a)};
}

#ifdef __FMA__
inline DoubleDouble twoProd(double a, double b)
{
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}
#else
// Without a hardware fused multiply-add (std::fma would be a slow library
// call), Dekker's product: split each factor into halves that multiply exactly.
inline DoubleDouble split(double a)
{
    const double t = 134217729.0 * a; // 2^27 + 1
    const double hi = t - (t - a);
    return {hi, a - hi};
}

inline DoubleDouble twoProd(double a, double b)
{
    const double p = a * b;
    const DoubleDouble x = split(a), y = split(b);
    return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}
#endif

// The "sloppy" sum (Dekker): one TwoSum; the low parts are added plainly,
// which loses accuracy only when the two operands nearly cancel.
inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b)
{
    DoubleDouble s = twoSum(a.hi, b.hi);
    s.lo += a.lo + b.lo;
    return quickTwoSum(s.hi, s.lo);
}

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b)
{
    DoubleDouble p = twoProd(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return quickTwoSum(p.hi, p.lo);
}

// A double-double times a double.
inline DoubleDouble operator*(const DoubleDouble& a, double b)
{
    DoubleDouble p = twoProd(a.hi, b);
    p.lo += a.lo * b;
    return quickTwoSum(p.hi, p.lo);
}

// 1 / b: a double quotient refined by one Newton step in double-double.
inline DoubleDouble reciprocal(const DoubleDouble& b)
{
    const double q = 1.0 / b.hi;
    // r = 1 - q b, carried exactly enough for the second digit.
    const DoubleDouble p = twoProd(q, b.hi);
    const double r = (1.0 - p.hi) - p.lo - q * b.lo;
    return quickTwoSum(q, r * q);
}

// p' = M p and the divide, for points given in double (x, y, z interleaved);
// results as double-double (hi and lo arrays, x, y, z interleaved).
inline void transformPointsDD(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count)
{
    for (std::size_t i = 0; i < count; ++i) {
        const double x = in[3 * i], y = in[3 * i + 1], z = in[3 * i + 2];
        DoubleDouble row[4];
        for (int r = 0; r < 4; ++r)
            row[r] = m.m[r][0] * x + m.m[r][1] * y + m.m[r][2] * z + m.m[r][3];
        const DoubleDouble inverse = reciprocal(row[3]);
        for (int a = 0; a < 3; ++a) {
            const DoubleDouble q = row[a] * inverse;
            hi[3 * i + a] = q.hi;
            lo[3 * i + a] = q.lo;
        }
    }
}

// One point given in double-double through the matrix and the divide (for
// the few points, such as the view volume's corners, whose exact position
// needs more than double).
inline std::array<DoubleDouble, 3> transformPointDD(const Mat4DD& m, const std::array<DoubleDouble, 3>& p)
{
    DoubleDouble row[4];
    for (int r = 0; r < 4; ++r)
        row[r] = m.m[r][0] * p[0] + m.m[r][1] * p[1] + m.m[r][2] * p[2] + m.m[r][3];
    const DoubleDouble inverse = reciprocal(row[3]);
    return {row[0] * inverse, row[1] * inverse, row[2] * inverse};
}

} // inline namespace

// transformPointsDD at the best speed this processor allows: with hardware
// fused multiply-add where it has it (most x86-64 since 2013), chosen at run time.
void transformPointsDoubleDouble(const Mat4DD& m, const double* in, double* hi, double* lo, std::size_t count);

} // namespace viewpipe
