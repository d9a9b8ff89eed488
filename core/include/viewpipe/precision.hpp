#pragma once

// Scalar types beyond long double, for the core's templates: binary128 from
// libquadmath and MPFR at a chosen precision, through Boost.Multiprecision
// (expression templates off, as Eigen needs plain value types).

#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>

namespace viewpipe {

using Float128 = boost::multiprecision::number<boost::multiprecision::float128_backend, boost::multiprecision::et_off>;
// MPFR with its precision set at run time (Mpfr::default_precision(digits10)).
using Mpfr = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;
// MPFR with 100 decimal digits (about 336 bits), fixed at compile time.
using Mpfr100 = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<100>, boost::multiprecision::et_off>;

} // namespace viewpipe
