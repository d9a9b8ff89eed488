#pragma once

// What a precision buys: the error of each quantity computed in a scalar type
// T against a reference computed from the same inputs in MPFR at 256 bits or
// more. Every error is returned in absolute terms; callers divide by the
// type's epsilon for units of epsilon. No timing here: that is the caller's.
//
// - maxRelativeError: max over N's entries of |N_T - N_ref| / |N_ref|, with
//   zero entries (below 1e-40 of the largest) measured against the largest |N_ref|.
// - cornerError: the view volume's 8 corners (exact, rounded to T) through
//   N_T and the divide, against the exact canonical corners (max coordinate).
// - orthogonalityError: max |R R^T - I| and determinantError |det R - 1|,
//   evaluated exactly for the R computed in T.
// - roundtripError: max |N^-1 (N p) - p| / max(1, |p|) in T over points
//   inside the view volume.
// - ndc*, pixel*: the scene's vertices through N (and Foley's M) and the
//   divide, against the reference, in NDC and in pixels of a viewport.

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "viewpipe/double_double.hpp"
#include "viewpipe/pipeline.hpp"
#include "viewpipe/setup.hpp"
#include "viewpipe/precision.hpp"
#include "viewpipe/transform.hpp"

namespace viewpipe {

using Reference = Mpfr;

struct Viewport {
    int width = 1920, height = 1080;
};

struct AccuracyMetrics {
    double maxRelativeError = 0;
    double cornerError = 0;
    double orthogonalityError = 0;
    double determinantError = 0;
    double roundtripError = 0;
    double ndcMaxError = 0, ndcRmsError = 0;
    double pixelMaxError = 0, pixelRmsError = 0;
};

// The reference: the pipeline in MPFR, the view volume's corners and their
// canonical images, points inside the volume, and the exact clip matrix.
struct ReferenceSolution {
    unsigned bits = 256;
    Pipeline<Reference> pipeline;
    Mat4<Reference> clip;                          // toClip * composite
    std::array<Vec3<Reference>, 8> corners;        // world
    std::array<Vec3<Reference>, 8> canonical;      // their exact images
    bool cornersDivide = false;                    // OpenGL: the canonical corners are after the divide
    bool farStandIn = false;                       // an infinite far plane: corners and interior end at gl::kStandInFar * near
    std::vector<Vec3<double>> interior;            // inside the view volume, exact in double
};

// Points inside a convex volume given by its corners: random convex
// combinations (weights in [0.05, 1)), seeded, so every run sees the same points.
template <class T>
std::vector<Vec3<double>> pointsInside(const std::array<Vec3<T>, 8>& corners, std::size_t count, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.05, 1.0);
    std::vector<Vec3<double>> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        Vec3<T> p = Vec3<T>::Zero();
        T total = 0;
        for (const Vec3<T>& corner : corners) {
            const double weight = unit(rng);
            p += T(weight) * corner;
            total += T(weight);
        }
        p /= total;
        points.emplace_back(static_cast<double>(p.x()), static_cast<double>(p.y()), static_cast<double>(p.z()));
    }
    return points;
}

inline unsigned digitsForBits(unsigned bits)
{
    return unsigned(std::ceil(bits * 0.30102999566398120)) + 1;
}

// Sets MPFR's working precision for everything made after the call.
inline void setReferenceBits(unsigned bits)
{
    Reference::default_precision(digitsForBits(bits));
}

inline ReferenceSolution makeReference(const CameraSpec<double>& camera, unsigned bits, std::size_t interiorPoints = 256)
{
    setReferenceBits(bits);
    ReferenceSolution ref;
    ref.bits = bits;
    const CameraSpec<Reference> exact = castCamera<Reference>(camera);
    ref.pipeline = buildPipeline(exact);
    ref.clip = ref.pipeline.clipMatrix();
    std::visit(
        [&](const auto& c) {
            using C = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<C, foley::ViewSpec<Reference>>) {
                ref.corners = foley::viewVolumeCorners(c);
                ref.canonical = foley::canonicalCorners(c);
            } else if (gl::hasFarFace(c)) {
                ref.corners = gl::viewVolumeCorners(c);
                ref.canonical = viewSetup(c).canonical;
                ref.cornersDivide = true;
            } else {
                // No far face: the volume measured ends at gl::kStandInFar times near, and every
                // corner's exact image is the reference's own (tests check the near face lands on
                // the API's canonical one and the stand-in on depth n / d).
                gl::Camera<Reference> bounded = c;
                std::visit([](auto& p) { p.zFar = Reference(gl::kStandInFar) * p.zNear; }, bounded.projection);
                ref.corners = gl::viewVolumeCorners(bounded);
                for (std::size_t k = 0; k < 8; ++k) {
                    const Vec4<Reference> h = ref.pipeline.composite * ref.corners[k].homogeneous();
                    ref.canonical[k] = h.template head<3>() / h.w();
                }
                ref.cornersDivide = true;
                ref.farStandIn = true;
            }
        },
        exact);
    ref.interior = pointsInside(ref.corners, interiorPoints, 12345); // rounded to double
    return ref;
}

// Max relative difference between two references' composites: how far the
// reference itself can be trusted (256 against 512 bits).
inline double referenceAgreement(const ReferenceSolution& a, const ReferenceSolution& b)
{
    setReferenceBits(std::max(a.bits, b.bits));
    Reference worst = 0;
    const Reference scale = b.pipeline.composite.cwiseAbs().maxCoeff();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            worst = std::max<Reference>(worst, abs(a.pipeline.composite(r, c) - b.pipeline.composite(r, c)) / scale);
    return static_cast<double>(worst);
}

namespace detail {

template <class T> Reference toReference(const T& x)
{
    return Reference(x);
}

template <> inline Reference toReference(const DoubleDouble& x)
{
    return Reference(x.hi) + Reference(x.lo);
}

template <class T> Mat4<Reference> toReference(const Mat4<T>& m)
{
    Mat4<Reference> out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out(r, c) = toReference(m(r, c));
    return out;
}

template <class T> T fromReference(const Reference& x)
{
    return static_cast<T>(x);
}

inline double maxRelative(const Mat4<Reference>& value, const Mat4<Reference>& exact)
{
    const Reference scale = exact.cwiseAbs().maxCoeff();
    Reference worst = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            // Entries that are zero up to the reference's own rounding count as zero.
            const bool zero = abs(exact(r, c)) <= scale * Reference("1e-40");
            const Reference denominator = zero ? scale : abs(exact(r, c));
            worst = std::max<Reference>(worst, abs(value(r, c) - exact(r, c)) / denominator);
        }
    return static_cast<double>(worst);
}

// Errors of projected points against the reference, in NDC and in pixels.
inline void screenErrors(const std::vector<Vec3<Reference>>& got, const std::vector<Vec3<Reference>>& exact,
                         const Viewport& viewport, AccuracyMetrics& out)
{
    Reference ndcMax = 0, ndcSquares = 0, pixelMax = 0, pixelSquares = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        const Vec3<Reference> d = got[i] - exact[i];
        const Reference ndc = d.template head<2>().cwiseAbs().maxCoeff();
        const Reference dx = d.x() * Reference(viewport.width) / 2, dy = d.y() * Reference(viewport.height) / 2;
        const Reference pixel = sqrt(dx * dx + dy * dy);
        ndcMax = std::max(ndcMax, ndc);
        pixelMax = std::max(pixelMax, pixel);
        ndcSquares += ndc * ndc;
        pixelSquares += pixel * pixel;
    }
    const Reference n = Reference(std::max<std::size_t>(1, got.size()));
    out.ndcMaxError = static_cast<double>(ndcMax);
    out.ndcRmsError = static_cast<double>(sqrt(ndcSquares / n));
    out.pixelMaxError = static_cast<double>(pixelMax);
    out.pixelRmsError = static_cast<double>(sqrt(pixelSquares / n));
}

inline std::vector<Vec3<Reference>> exactImages(const ReferenceSolution& ref, const std::vector<Vec3<double>>& points)
{
    std::vector<Vec3<Reference>> out;
    for (const Vec3<double>& p : points) {
        const Vec4<Reference> h = ref.clip * Vec4<Reference>(Reference(p.x()), Reference(p.y()), Reference(p.z()), 1);
        out.push_back(h.template head<3>() / h.w());
    }
    return out;
}

template <class Pipe> void rotationErrors(const Pipe& pipeline, AccuracyMetrics& out)
{
    const Mat4<Reference> r4 = toReference(pipeline.stages[1].matrix); // R, or R_eye
    const Mat3<Reference> r = r4.template topLeftCorner<3, 3>();
    out.orthogonalityError = static_cast<double>((r * r.transpose() - Mat3<Reference>::Identity()).cwiseAbs().maxCoeff());
    out.determinantError = static_cast<double>(abs(r.determinant() - 1));
}

} // namespace detail

// The metrics of scalar type T (float, double, long double, Float128, Mpfr).
// Everything in T is computed first, at T's precision (for Mpfr, the one set
// when the call is made); the comparison then runs at the reference's.
template <class T>
AccuracyMetrics measureAccuracy(const CameraSpec<double>& camera, const std::vector<Vec3<double>>& vertices,
                                const ReferenceSolution& ref, const Viewport& viewport)
{
    using detail::toReference;
    const Pipeline<T> p = buildPipeline(castCamera<T>(camera));

    std::array<Vec4<T>, 8> corners;
    for (std::size_t k = 0; k < 8; ++k) {
        const Vec4<T> world(detail::fromReference<T>(ref.corners[k].x()), detail::fromReference<T>(ref.corners[k].y()),
                            detail::fromReference<T>(ref.corners[k].z()), T(1));
        corners[k] = p.composite * world;
        if (ref.cornersDivide)
            corners[k] /= corners[k].w();
    }
    const Mat4<T> inverse = p.composite.inverse();
    std::vector<Vec3<T>> roundtrips;
    for (const Vec3<double>& q : ref.interior) {
        const Vec4<T> back = inverse * (p.composite * Vec4<T>(T(q.x()), T(q.y()), T(q.z()), T(1)));
        roundtrips.push_back(back.template head<3>() / back.w());
    }
    const Mat4<T> clip = p.clipMatrix();
    std::vector<T> in(3 * vertices.size()), result(3 * vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        for (int a = 0; a < 3; ++a)
            in[3 * i + std::size_t(a)] = T(vertices[i][a]);
    transformPoints(clip, in.data(), result.data(), vertices.size());

    setReferenceBits(ref.bits);
    AccuracyMetrics out;
    out.maxRelativeError = detail::maxRelative(toReference(p.composite), ref.pipeline.composite);
    detail::rotationErrors(p, out);
    Reference corner = 0;
    for (std::size_t k = 0; k < 8; ++k)
        for (int a = 0; a < 3; ++a)
            corner = std::max<Reference>(corner, abs(toReference(corners[k][a]) - ref.canonical[k][a]));
    out.cornerError = static_cast<double>(corner);
    Reference roundtrip = 0;
    for (std::size_t i = 0; i < roundtrips.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            const Reference exact(ref.interior[i][a]);
            roundtrip = std::max<Reference>(roundtrip, abs(toReference(roundtrips[i][a]) - exact) /
                                                           std::max<Reference>(1, abs(exact)));
        }
    out.roundtripError = static_cast<double>(roundtrip);
    std::vector<Vec3<Reference>> got;
    for (std::size_t i = 0; i < vertices.size(); ++i)
        got.emplace_back(toReference(result[3 * i]), toReference(result[3 * i + 1]), toReference(result[3 * i + 2]));
    detail::screenErrors(got, detail::exactImages(ref, vertices), viewport, out);
    return out;
}

// The double-double tier: the matrices are built in binary128 and held as
// double-double; vertices (given in double) and corners (exact, rounded to
// double-double) go through the double-double transform.
inline Mat4DD toDoubleDouble(const Mat4<Float128>& m)
{
    Mat4DD out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const double hi = static_cast<double>(m(r, c));
            out.m[r][c] = {hi, static_cast<double>(m(r, c) - Float128(hi))};
        }
    return out;
}

inline AccuracyMetrics measureDoubleDoubleAccuracy(const CameraSpec<double>& camera,
                                                   const std::vector<Vec3<double>>& vertices,
                                                   const ReferenceSolution& ref, const Viewport& viewport)
{
    using detail::toReference;
    AccuracyMetrics out = measureAccuracy<Float128>(camera, {}, ref, viewport); // R and the round trip
    const Pipeline<Float128> p = buildPipeline(castCamera<Float128>(camera));
    const Mat4DD composite = toDoubleDouble(p.composite);
    const Mat4DD clip = toDoubleDouble(Mat4<Float128>(p.clipMatrix()));
    setReferenceBits(ref.bits);
    Mat4<Reference> entries;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            entries(r, c) = toReference(composite.m[r][c]);
    out.maxRelativeError = detail::maxRelative(entries, ref.pipeline.composite);

    auto transform = [](const Mat4DD& m, const std::vector<Vec3<double>>& points) {
        std::vector<double> in, hi(3 * points.size()), lo(3 * points.size());
        for (const Vec3<double>& q : points)
            in.insert(in.end(), {q.x(), q.y(), q.z()});
        transformPointsDoubleDouble(m, in.data(), hi.data(), lo.data(), points.size());
        std::vector<Vec3<Reference>> out;
        for (std::size_t i = 0; i < points.size(); ++i)
            out.emplace_back(toReference(DoubleDouble{hi[3 * i], lo[3 * i]}),
                             toReference(DoubleDouble{hi[3 * i + 1], lo[3 * i + 1]}),
                             toReference(DoubleDouble{hi[3 * i + 2], lo[3 * i + 2]}));
        return out;
    };
    // Corners: exact in the reference, rounded to double-double.
    auto split = [](const Reference& x) {
        const double hi = static_cast<double>(x);
        return DoubleDouble{hi, static_cast<double>(x - Reference(hi))};
    };
    Mat4DD cornerMatrix = composite;
    if (!ref.cornersDivide) // an affine image: w is exactly 1
        cornerMatrix.m[3][0] = cornerMatrix.m[3][1] = cornerMatrix.m[3][2] = {0, 0}, cornerMatrix.m[3][3] = {1, 0};
    Reference corner = 0;
    for (std::size_t k = 0; k < 8; ++k) {
        const auto image = transformPointDD(
            cornerMatrix, {split(ref.corners[k].x()), split(ref.corners[k].y()), split(ref.corners[k].z())});
        for (int a = 0; a < 3; ++a)
            corner = std::max<Reference>(corner, abs(toReference(image[std::size_t(a)]) - ref.canonical[k][a]));
    }
    out.cornerError = static_cast<double>(corner);
    detail::screenErrors(transform(clip, vertices), detail::exactImages(ref, vertices), viewport, out);
    return out;
}

} // namespace viewpipe
