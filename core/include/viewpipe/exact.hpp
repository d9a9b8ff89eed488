#pragma once

// Exact numbers for the core's templates: the rationals a person types and the
// square roots the pipeline takes (normalizing VPN, VUP x n, lookAt's
// directions). A value is a sum of rational multiples of square roots of
// distinct square-free integers; these roots are linearly independent over the
// rationals, so the form is unique and a zero test or a sign is exact. A value
// that is no such sum (the cotangent of most angles, a nested root) is kept to
// 50 digits and marked inexact with the reason, and so is all it touches.
// Built on Boost.Multiprecision's header-only integers: the page's WebAssembly
// computes with the same type.

#include <Eigen/Core>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>

namespace viewpipe {

using BigInt = boost::multiprecision::cpp_int;
using Rational = boost::multiprecision::cpp_rational;
using Approximation =
    boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>, boost::multiprecision::et_off>;

class Exact {
public:
    Exact() = default;
    template <class I, std::enable_if_t<std::is_integral_v<I>, int> = 0> Exact(I value) : Exact(Rational(value)) {}
    Exact(const Rational& value);
    // The binary value the double holds (its own rational), an infinity kept as one.
    explicit Exact(double value);
    // A decimal as written ("0.1" is one tenth): fromDecimal's way in.
    explicit Exact(const std::string& decimal);
    static Exact inexact(const Approximation& value, std::string reason);

    bool isExact() const { return !approximation_; }
    const std::string& inexactReason() const; // empty when exact
    bool isRational() const { return isExact() && infinity_ == 0 && (terms_.empty() || (terms_.size() == 1 && terms_.begin()->first == 1)); }
    Rational rational() const; // the value, when isRational()
    int sign() const;          // -1, 0 or 1, decided exactly when exact
    bool isInfinite() const { return infinity_ != 0; }
    // Zero exactly: what an inexact value times it, or plus it, is exactly (a rotation's 0 entries stay 0
    // beside gluPerspective's inexact cot).
    bool isExactZero() const { return isExact() && infinity_ == 0 && terms_.empty(); }

    Approximation approximation() const;
    explicit operator double() const;
    explicit operator float() const { return float(double(*this)); }
    explicit operator long double() const;

    // Integers, + - * /, sqrt(...) and parentheses, as Python reads it with
    // math.sqrt: "-13/36", "sqrt(2)/2", "1 + 20*sqrt(2)". Inexact: 40 digits.
    std::string text() const;
    // "-\frac{13}{36}", "\frac{\sqrt{2}}{2}"; inexact: `digits` significant digits.
    std::string latex(int digits = 6) const;
    // Short enough to read exactly, as a textbook writes it: a fraction of up
    // to 9 digits, one root term with up to 4, or an integer and an integer
    // times a root, of up to 3 (-13/36, 42/1475, 19*sqrt(482)/482, Foley's
    // z_min 11 - 8*sqrt(2)); 23/4 + 23*sqrt(2)/16 is too wide for a matrix cell.
    // A decimal reads better than 187*sqrt(1068594)/1068594, a sum of roots, or
    // a scene's 0.5773502691896258 taken exactly.
    bool readsExactly() const;

    Exact operator-() const;
    Exact& operator+=(const Exact& b);
    Exact& operator-=(const Exact& b) { return *this += -b; }
    Exact& operator*=(const Exact& b);
    Exact& operator/=(const Exact& b);

    friend Exact operator+(Exact a, const Exact& b) { return a += b; }
    friend Exact operator-(Exact a, const Exact& b) { return a -= b; }
    friend Exact operator*(Exact a, const Exact& b) { return a *= b; }
    friend Exact operator/(Exact a, const Exact& b) { return a /= b; }
    friend bool operator==(const Exact& a, const Exact& b) { return compare(a, b) == 0; }
    friend bool operator!=(const Exact& a, const Exact& b) { return compare(a, b) != 0; }
    friend bool operator<(const Exact& a, const Exact& b) { return compare(a, b) < 0; }
    friend bool operator<=(const Exact& a, const Exact& b) { return compare(a, b) <= 0; }
    friend bool operator>(const Exact& a, const Exact& b) { return compare(a, b) > 0; }
    friend bool operator>=(const Exact& a, const Exact& b) { return compare(a, b) >= 0; }

    friend Exact sqrt(const Exact& x);

private:
    static int compare(const Exact& a, const Exact& b);
    Exact& taint(const Exact& other); // inexact where `other` is
    void simplify();

    // Square-free radicand (1 for the rational part) -> nonzero coefficient.
    std::map<BigInt, Rational> terms_;
    std::shared_ptr<const Approximation> approximation_; // set when inexact
    std::shared_ptr<const std::string> reason_;
    int infinity_ = 0; // +1 or -1 for an infinite far plane
};

Exact sqrt(const Exact& x);
inline Exact abs(const Exact& x) { return x.sign() < 0 ? -x : x; }
inline bool isfinite(const Exact& x) { return !x.isInfinite(); }
inline bool isinf(const Exact& x) { return x.isInfinite(); }
inline bool isnan(const Exact&) { return false; }
inline Exact fma(const Exact& a, const Exact& b, const Exact& c) { return a * b + c; }
std::ostream& operator<<(std::ostream& out, const Exact& x);

// An exact expression as a person types it: integers, decimals (with an
// exponent), + - * /, sqrt(...) or the sign √, and parentheses ("20*sqrt(2)",
// "1/3", "√2/2"). Throws std::invalid_argument with the reason
// ("the square root of -1, a negative number"); callers name the field.
Exact parseExact(std::string_view text);

// cot(degrees / 2) exactly where it is a square-root expression (half-angles
// that are multiples of 15 or 22.5 degrees), else to 50 digits marked inexact.
Exact cotOfHalfDegrees(const Exact& degrees);

} // namespace viewpipe

namespace Eigen {
template <> struct NumTraits<viewpipe::Exact> : GenericNumTraits<viewpipe::Exact> {
    using Real = viewpipe::Exact;
    using NonInteger = viewpipe::Exact;
    using Nested = viewpipe::Exact;
    using Literal = viewpipe::Exact;
    enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = 1, AddCost = 20, MulCost = 40 };
    static Real epsilon() { return 0; }
    static Real dummy_precision() { return 0; }
    static int digits10() { return 40; }
};
} // namespace Eigen
