#pragma once

// Scalar types beyond long double, for the core's templates: binary128 from
// libquadmath and MPFR at a chosen precision, through Boost.Multiprecision
// (expression templates off, as Eigen needs plain value types).

#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <charconv>
#include <string>

namespace viewpipe {

using Float128 = boost::multiprecision::number<boost::multiprecision::float128_backend, boost::multiprecision::et_off>;
// MPFR with its precision set at run time (Mpfr::default_precision(digits10)).
using Mpfr = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;
// MPFR with 100 decimal digits (about 336 bits), fixed at compile time.
using Mpfr100 = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<100>, boost::multiprecision::et_off>;

// The shortest decimal that reads back as x: a scene's numbers as they were
// written in the file ("0.1", not 0.1000000000000000055...).
inline std::string shortestDecimal(double x)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, result.ptr);
}

// x as the decimal it was written as, in a wider type.
template <class T> T fromDecimal(double x)
{
    return T(shortestDecimal(x));
}

} // namespace viewpipe
