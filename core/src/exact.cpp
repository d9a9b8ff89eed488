#include "viewpipe/exact.hpp"

#include <boost/multiprecision/miller_rabin.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <set>
#include <stdexcept>
#include <vector>

namespace viewpipe {
namespace {

using Terms = std::map<BigInt, Rational>;

const std::string kNoReason;

Approximation approximate(const Rational& q)
{
    return Approximation(boost::multiprecision::numerator(q)) / Approximation(boost::multiprecision::denominator(q));
}

Approximation approximate(const Terms& terms)
{
    Approximation sum = 0;
    for (const auto& [radicand, coefficient] : terms)
        sum += approximate(coefficient) * (radicand == 1 ? Approximation(1) : sqrt(Approximation(radicand)));
    return sum;
}

int signOf(const Rational& q)
{
    return q > 0 ? 1 : q < 0 ? -1 : 0;
}

// The sign of a sum of rational multiples of distinct square-free roots: the
// sum is zero only when empty, so bounds on the roots narrowed until they
// exclude zero decide it.
int signOf(const Terms& terms)
{
    if (terms.empty())
        return 0;
    if (terms.size() == 1)
        return signOf(terms.begin()->second);
    for (unsigned bits = 64;; bits *= 2) {
        const BigInt scale = BigInt(1) << bits;
        Rational low = 0, high = 0;
        for (const auto& [radicand, coefficient] : terms) {
            if (radicand == 1) {
                low += coefficient;
                high += coefficient;
                continue;
            }
            const BigInt root = boost::multiprecision::sqrt(BigInt(radicand << (2 * bits))); // floor(sqrt(r) 2^bits)
            const Rational below(root, scale), above(BigInt(root + 1), scale);
            low += coefficient * (coefficient > 0 ? below : above);
            high += coefficient * (coefficient > 0 ? above : below);
        }
        if (low > 0)
            return 1;
        if (high < 0)
            return -1;
    }
}

// sqrt(a) sqrt(b) = g sqrt(a b / g^2), g = gcd(a, b): square-free again.
BigInt productRadicand(const BigInt& a, const BigInt& b, BigInt& factor)
{
    factor = boost::multiprecision::gcd(a, b);
    return (a / factor) * (b / factor);
}

Terms multiply(const Terms& a, const Terms& b)
{
    Terms product;
    for (const auto& [ra, qa] : a)
        for (const auto& [rb, qb] : b) {
            BigInt factor;
            const BigInt radicand = productRadicand(ra, rb, factor);
            product[radicand] += qa * qb * Rational(factor);
        }
    for (auto it = product.begin(); it != product.end();)
        it = it->second == 0 ? product.erase(it) : std::next(it);
    return product;
}

constexpr unsigned long kTrialDivisionLimit = 1UL << 16;

// m = s^2 f with f square-free, when the factors can be found: trial division
// to 2^16; a rest below 2^48 without such factors is a prime, a product of two
// primes or a square; a larger one is accepted when it is a probable prime.
bool splitSquares(BigInt m, BigInt& s, BigInt& f)
{
    s = 1;
    f = 1;
    auto divideOut = [&](unsigned long p) {
        unsigned count = 0;
        while (m % p == 0) {
            m /= p;
            ++count;
        }
        for (unsigned k = 0; k < count / 2; ++k)
            s *= p;
        if (count % 2)
            f *= p;
    };
    divideOut(2);
    for (unsigned long p = 3; p <= kTrialDivisionLimit && BigInt(p) * p <= m; p += 2)
        divideOut(p);
    if (m == 1)
        return true;
    const BigInt root = boost::multiprecision::sqrt(m);
    if (root * root == m) {
        s *= root;
        return true;
    }
    const BigInt limit(kTrialDivisionLimit);
    if (m < limit * limit * limit || boost::multiprecision::miller_rabin_test(m, 25)) {
        f *= m;
        return true;
    }
    return false;
}

std::string integerText(const BigInt& n)
{
    return n.str();
}

// The terms as a sum, each written by term(p, radicand, q) for its coefficient's size p/q, with the
// signs between: in order, the rational part first, except that a positive term leads where there is
// one, as a textbook writes it: sqrt(2) - 1, 48*sqrt(2)/5 - 64/5 (-64/5 + ... looked negative).
template <class F> std::string joinTerms(const Terms& terms, F&& term)
{
    std::vector<std::pair<BigInt, Rational>> ordered(terms.begin(), terms.end());
    const auto positive = std::find_if(ordered.begin(), ordered.end(), [](const auto& t) { return t.second > 0; });
    if (positive != ordered.end())
        std::rotate(ordered.begin(), positive, positive + 1);
    std::string out;
    for (const auto& [radicand, coefficient] : ordered) {
        out += out.empty() ? (coefficient < 0 ? "-" : "") : (coefficient < 0 ? " - " : " + ");
        out += term(BigInt(abs(boost::multiprecision::numerator(coefficient))), radicand,
                    BigInt(boost::multiprecision::denominator(coefficient)));
    }
    return out;
}

constexpr std::size_t kMaxRoots = 64;

// The roots a value's roots generate: every product of some of them, reduced;
// stops past kMaxRoots (they double with each independent root).
std::vector<BigInt> generatedRadicands(const Terms& terms)
{
    std::set<BigInt> all{BigInt(1)};
    for (const auto& term : terms) {
        const std::set<BigInt> before = all;
        for (const BigInt& r : before) {
            BigInt factor;
            all.insert(productRadicand(r, term.first, factor));
        }
        if (all.size() > kMaxRoots)
            break;
    }
    return {all.begin(), all.end()};
}

// 1 / x in the field x's roots generate, by solving x y = 1 over the basis of
// their products; false when the basis is too large.
bool invert(const Terms& x, Terms& inverse)
{
    if (x.size() == 1) { // q sqrt(r): sqrt(r) / (q r)
        const auto& [radicand, coefficient] = *x.begin();
        inverse = {{radicand, Rational(1) / (coefficient * Rational(radicand))}};
        return true;
    }
    const std::vector<BigInt> basis = generatedRadicands(x);
    if (basis.size() > kMaxRoots)
        return false;
    const std::size_t n = basis.size();
    std::map<BigInt, std::size_t> index;
    for (std::size_t i = 0; i < n; ++i)
        index[basis[i]] = i;
    std::vector<std::vector<Rational>> a(n, std::vector<Rational>(n + 1, Rational(0)));
    for (std::size_t j = 0; j < n; ++j)
        for (const auto& [radicand, coefficient] : multiply(x, {{basis[j], Rational(1)}}))
            a[index.at(radicand)][j] = coefficient;
    a[index.at(BigInt(1))][n] = 1;
    for (std::size_t column = 0; column < n; ++column) {
        std::size_t pivot = column;
        while (a[pivot][column] == 0)
            ++pivot; // x is not zero, so multiplying by it is invertible
        std::swap(a[pivot], a[column]);
        for (std::size_t row = 0; row < n; ++row) {
            if (row == column || a[row][column] == 0)
                continue;
            const Rational ratio = a[row][column] / a[column][column];
            for (std::size_t k = column; k <= n; ++k)
                a[row][k] -= ratio * a[column][k];
        }
    }
    inverse.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (a[i][n] != 0)
            inverse[basis[i]] = a[i][n] / a[i][i];
    return true;
}

bool isSquare(const BigInt& n, BigInt& root)
{
    root = boost::multiprecision::sqrt(n);
    return root * root == n;
}

} // namespace

Exact::Exact(const Rational& value)
{
    if (value != 0)
        terms_[1] = value;
}

Exact::Exact(double value)
{
    if (std::isnan(value))
        throw std::invalid_argument("is not a number");
    if (std::isinf(value)) {
        infinity_ = value > 0 ? 1 : -1;
        return;
    }
    int exponent = 0;
    const double mantissa = std::frexp(value, &exponent);
    const BigInt digits = static_cast<long long>(std::ldexp(mantissa, 53)); // exact: 53 bits
    exponent -= 53;
    const Rational q = exponent >= 0 ? Rational(BigInt(digits << exponent))
                                     : Rational(digits, BigInt(BigInt(1) << -exponent));
    if (q != 0)
        terms_[1] = q;
}

Exact::Exact(const std::string& decimal)
{
    if (decimal == "inf" || decimal == "-inf")
        infinity_ = decimal == "inf" ? 1 : -1;
    else
        *this = parseExact(decimal);
}

Exact Exact::inexact(const Approximation& value, std::string reason)
{
    Exact x;
    x.approximation_ = std::make_shared<const Approximation>(value);
    x.reason_ = std::make_shared<const std::string>(std::move(reason));
    return x;
}

const std::string& Exact::inexactReason() const
{
    return reason_ ? *reason_ : kNoReason;
}

Rational Exact::rational() const
{
    return terms_.empty() ? Rational(0) : terms_.begin()->second;
}

int Exact::sign() const
{
    if (infinity_)
        return infinity_;
    if (approximation_)
        return *approximation_ > 0 ? 1 : *approximation_ < 0 ? -1 : 0;
    return signOf(terms_);
}

Approximation Exact::approximation() const
{
    if (infinity_)
        return infinity_ * std::numeric_limits<Approximation>::infinity();
    return approximation_ ? *approximation_ : approximate(terms_);
}

Exact::operator double() const
{
    if (infinity_)
        return infinity_ * std::numeric_limits<double>::infinity();
    if (isRational()) // rounded once, to the nearest double: a typed 0.1 is 0.1
        return rational().convert_to<double>();
    return approximation().convert_to<double>();
}

Exact::operator long double() const
{
    if (infinity_)
        return infinity_ * std::numeric_limits<long double>::infinity();
    if (isRational())
        return rational().convert_to<long double>();
    return approximation().convert_to<long double>();
}

std::string Exact::text() const
{
    if (infinity_)
        return infinity_ > 0 ? "inf" : "-inf";
    if (approximation_)
        return approximation_->str(40);
    if (terms_.empty())
        return "0";
    return joinTerms(terms_, [](const BigInt& p, const BigInt& radicand, const BigInt& q) {
        const std::string term =
            radicand == 1 ? integerText(p) : (p == 1 ? "" : integerText(p) + "*") + "sqrt(" + integerText(radicand) + ")";
        return term + (q == 1 ? "" : "/" + integerText(q));
    });
}

std::string Exact::latex(int digits) const
{
    if (infinity_)
        return infinity_ > 0 ? "\\infty" : "-\\infty";
    if (approximation_)
        return approximation_->str(digits);
    if (terms_.empty())
        return "0";
    return joinTerms(terms_, [](const BigInt& p, const BigInt& radicand, const BigInt& q) {
        const std::string numerator =
            radicand == 1 ? integerText(p) : (p == 1 ? "" : integerText(p)) + "\\sqrt{" + integerText(radicand) + "}";
        return q == 1 ? numerator : "\\frac{" + numerator + "}{" + integerText(q) + "}";
    });
}

bool Exact::readsExactly() const
{
    if (!isExact() || infinity_ || terms_.size() > 2)
        return false;
    if (terms_.size() == 2) // an integer and an integer times a root, each of up to 3 digits: 11 - 8*sqrt(2)
        return terms_.begin()->first == 1 && std::all_of(terms_.begin(), terms_.end(), [](const auto& term) {
                   return boost::multiprecision::denominator(term.second) == 1 &&
                          abs(boost::multiprecision::numerator(term.second)) < 1000 && term.first < 10000;
               });
    const BigInt limit = boost::multiprecision::pow(BigInt(10), isRational() ? 9u : 4u);
    for (const auto& [radicand, coefficient] : terms_)
        if (radicand >= limit || abs(boost::multiprecision::numerator(coefficient)) >= limit ||
            boost::multiprecision::denominator(coefficient) >= limit)
            return false;
    return true;
}

Exact Exact::operator-() const
{
    Exact x = *this;
    x.infinity_ = -infinity_;
    for (auto& term : x.terms_)
        term.second = -term.second;
    if (approximation_)
        x.approximation_ = std::make_shared<const Approximation>(-*approximation_);
    return x;
}

Exact& Exact::taint(const Exact& other)
{
    if (!reason_)
        reason_ = other.reason_;
    return *this;
}

Exact& Exact::operator+=(const Exact& b)
{
    if (infinity_ || b.infinity_) {
        if (infinity_ && b.infinity_ && infinity_ != b.infinity_)
            throw std::domain_error("infinity minus infinity");
        infinity_ = infinity_ ? infinity_ : b.infinity_;
        terms_.clear();
        return *this;
    }
    if (b.isExactZero())
        return *this;
    if (isExactZero())
        return *this = b;
    if (approximation_ || b.approximation_) {
        const std::shared_ptr<const std::string> reason = reason_ ? reason_ : b.reason_;
        *this = inexact(approximation() + b.approximation(), *reason);
        return *this;
    }
    for (const auto& [radicand, coefficient] : b.terms_) {
        Rational& sum = terms_[radicand];
        sum += coefficient;
        if (sum == 0)
            terms_.erase(radicand);
    }
    return *this;
}

Exact& Exact::operator*=(const Exact& b)
{
    if (infinity_ || b.infinity_) {
        const int product = sign() * b.sign();
        if (product == 0)
            throw std::domain_error("zero times infinity");
        *this = Exact();
        infinity_ = product;
        return *this;
    }
    if (isExactZero() || b.isExactZero())
        return *this = Exact();
    if (approximation_ || b.approximation_) {
        const std::shared_ptr<const std::string> reason = reason_ ? reason_ : b.reason_;
        *this = inexact(approximation() * b.approximation(), *reason);
        return *this;
    }
    if (terms_.size() * b.terms_.size() > kMaxRoots * kMaxRoots) { // a product of sums of many roots
        *this = inexact(approximation() * b.approximation(), "a product of more than " +
                                                                 std::to_string(kMaxRoots * kMaxRoots) + " terms");
        return *this;
    }
    terms_ = multiply(terms_, b.terms_);
    return *this;
}

Exact& Exact::operator/=(const Exact& b)
{
    if (b.sign() == 0)
        throw std::domain_error("division by zero");
    if (b.infinity_) {
        if (infinity_)
            throw std::domain_error("infinity divided by infinity");
        return *this = Exact(); // a finite value over an infinite far plane
    }
    if (infinity_) {
        infinity_ *= b.sign();
        return *this;
    }
    if (isExactZero())
        return *this;
    if (approximation_ || b.approximation_) {
        const std::shared_ptr<const std::string> reason = reason_ ? reason_ : b.reason_;
        *this = inexact(approximation() / b.approximation(), *reason);
        return *this;
    }
    Terms inverse;
    if (!invert(b.terms_, inverse)) {
        *this = inexact(approximation() / b.approximation(), "a quotient of more than " + std::to_string(kMaxRoots) +
                                                                 " distinct square roots");
        return *this;
    }
    terms_ = multiply(terms_, inverse);
    return *this;
}

int Exact::compare(const Exact& a, const Exact& b)
{
    if (a.infinity_ || b.infinity_)
        return a.infinity_ == b.infinity_ ? 0 : a.infinity_ > b.infinity_ ? 1 : -1;
    return (a - b).sign();
}

Exact sqrt(const Exact& x)
{
    const int sign = x.sign();
    if (sign < 0)
        throw std::domain_error("the square root of " + x.text() + ", a negative number");
    if (sign == 0 || x.infinity_)
        return x;
    if (x.approximation_)
        return Exact::inexact(sqrt(*x.approximation_), *x.reason_);
    const std::string nested = "the square root of " + x.text() + " is no sum of square roots of rationals";
    if (x.isRational()) { // sqrt(p/q) = sqrt(p q) / q
        const Rational q = x.rational();
        BigInt square, free;
        if (!splitSquares(BigInt(boost::multiprecision::numerator(q) * boost::multiprecision::denominator(q)), square,
                          free))
            return Exact::inexact(sqrt(x.approximation()),
                                  "the square root of " + x.text() + " has a square factor too large to find");
        Exact root;
        root.terms_[free] = Rational(square, boost::multiprecision::denominator(q));
        return root;
    }
    // a + b sqrt(r) = (sqrt((a + s)/2) + sign(b) sqrt((a - s)/2))^2 when s^2 = a^2 - b^2 r is a rational square.
    if (x.terms_.size() == 2 && x.terms_.begin()->first == 1) {
        const Rational& a = x.terms_.begin()->second;
        const auto& [r, b] = *std::next(x.terms_.begin());
        const Rational s2 = a * a - b * b * Rational(r);
        BigInt p, q;
        if (s2 >= 0 && isSquare(boost::multiprecision::numerator(s2), p) &&
            isSquare(boost::multiprecision::denominator(s2), q)) {
            const Exact s = Rational(p, q);
            const Exact half = Rational(1, 2);
            Exact root = sqrt((Exact(a) + s) * half);
            const Exact other = sqrt((Exact(a) - s) * half);
            root = b > 0 ? root + other : root - other;
            if (root.isExact() && root * root == x && root.sign() > 0)
                return root;
        }
    }
    return Exact::inexact(sqrt(x.approximation()), nested);
}

std::ostream& operator<<(std::ostream& out, const Exact& x)
{
    return out << x.text();
}

namespace {

constexpr std::string_view kRootSign = "\u221A";

// Integers, decimals, + - * /, sqrt(...), the sign √, parentheses.
class ExpressionParser {
public:
    explicit ExpressionParser(std::string_view text) : text_(text) {}

    Exact parse()
    {
        skipSpaces();
        if (at_ == text_.size())
            throw std::invalid_argument("is empty: write a number or an expression such as 20*sqrt(2) or 1/3");
        Exact value = sum();
        if (at_ != text_.size())
            fail("unexpected \"" + std::string(text_.substr(at_, 1)) + "\"");
        return value;
    }

private:
    [[noreturn]] void fail(const std::string& what) const
    {
        throw std::invalid_argument(what + " at character " + std::to_string(at_ + 1) + " of \"" + std::string(text_) +
                                    "\"");
    }

    void skipSpaces()
    {
        while (at_ < text_.size() && text_[at_] == ' ')
            ++at_;
    }

    bool take(std::string_view token)
    {
        skipSpaces();
        if (text_.substr(at_, token.size()) != token)
            return false;
        at_ += token.size();
        return true;
    }

    bool takeMinus() { return take("-") || take("\u2212"); } // the minus sign a word processor writes

    Exact sum()
    {
        Exact value = product();
        for (;;) {
            if (take("+"))
                value += product();
            else if (takeMinus())
                value -= product();
            else
                return value;
        }
    }

    Exact product()
    {
        Exact value = unary();
        for (;;) {
            if (take("*")) {
                value *= unary();
            } else if (take("/")) {
                const std::size_t divisorAt = at_;
                const Exact divisor = unary();
                if (divisor.sign() == 0) {
                    at_ = divisorAt;
                    fail("division by zero");
                }
                value /= divisor;
            } else if (skipSpaces(), text_.substr(at_, kRootSign.size()) == kRootSign) {
                value *= unary(); // 20√2
            } else {
                return value;
            }
        }
    }

    Exact unary()
    {
        // Every nesting (parentheses, roots, signs) passes here: a bound keeps the stack.
        if (++depth_ > kMaxDepth)
            fail("nested deeper than " + std::to_string(kMaxDepth) + " levels");
        Exact value = take("+") ? unary() : takeMinus() ? -unary() : primary();
        --depth_;
        return value;
    }

    Exact root(std::size_t start, const Exact& argument)
    {
        if (argument.sign() < 0) {
            at_ = start;
            fail("the square root of " + argument.text() + ", a negative number,");
        }
        return sqrt(argument);
    }

    Exact primary()
    {
        skipSpaces();
        const std::size_t start = at_;
        if (take("sqrt")) {
            if (!take("("))
                fail("expected ( after sqrt");
            const Exact argument = sum();
            if (!take(")"))
                fail("expected )");
            return root(start, argument);
        }
        if (take(kRootSign)) // √2, √(2)
            return root(start, primary());
        if (take("(")) {
            const Exact value = sum();
            if (!take(")"))
                fail("expected )");
            return value;
        }
        return number();
    }

    Exact number()
    {
        skipSpaces();
        const std::size_t start = at_;
        BigInt digits = 0;
        int scale = 0; // value = digits * 10^scale
        bool any = false;
        auto isDigit = [&] { return at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9'; };
        while (isDigit()) {
            digits = digits * 10 + (text_[at_++] - '0');
            any = true;
        }
        if (at_ < text_.size() && text_[at_] == '.') {
            ++at_;
            while (isDigit()) {
                digits = digits * 10 + (text_[at_++] - '0');
                --scale;
                any = true;
            }
        }
        if (!any) {
            at_ = start;
            fail("expected a number, sqrt(...) or (");
        }
        if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
            ++at_;
            const bool negative = at_ < text_.size() && text_[at_] == '-';
            if (at_ < text_.size() && (text_[at_] == '-' || text_[at_] == '+'))
                ++at_;
            int exponent = 0;
            if (!isDigit())
                fail("expected the exponent's digits");
            while (isDigit()) {
                exponent = exponent * 10 + (text_[at_++] - '0');
                if (exponent > 1000)
                    fail("the exponent is larger than 1000");
            }
            scale += negative ? -exponent : exponent;
        }
        const BigInt power = boost::multiprecision::pow(BigInt(10), static_cast<unsigned>(std::abs(scale)));
        return scale >= 0 ? Exact(Rational(digits * power)) : Exact(Rational(digits, power));
    }

    static constexpr int kMaxDepth = 100;
    std::string_view text_;
    std::size_t at_ = 0;
    int depth_ = 0;
};

} // namespace

Exact parseExact(std::string_view text)
{
    return ExpressionParser(text).parse();
}

Exact cotOfHalfDegrees(const Exact& degrees)
{
    if (degrees.isRational()) {
        const Rational half = degrees.rational() / 2;
        const Exact root2 = sqrt(Exact(2)), root3 = sqrt(Exact(3));
        const std::pair<Rational, Exact> known[] = {
            {15, Exact(2) + root3},         {Rational(45, 2), Exact(1) + root2}, {30, root3},
            {45, Exact(1)},                 {60, root3 / Exact(3)},              {Rational(135, 2), root2 - Exact(1)},
            {75, Exact(2) - root3}};
        for (const auto& [angle, cotangent] : known)
            if (half == angle)
                return cotangent;
    }
    const Approximation radians = degrees.approximation() / 2 * acos(Approximation(-1)) / 180;
    return Exact::inexact(1 / tan(radians), "cot(" + degrees.text() +
                                                " degrees / 2) is not a square-root expression (exact at 30, 45, 60, "
                                                "90, 120, 135 and 150 degrees)");
}

} // namespace viewpipe
