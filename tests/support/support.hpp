#pragma once

// Shared helpers for the core and numerics tests: seeded random valid specifications and
// tolerances stated in units of the scalar type's epsilon.

#include <gtest/gtest.h>

#include <random>

#include "viewpipe/pipeline.hpp"

namespace viewpipe::test {

using ScalarTypes = ::testing::Types<float, double, long double>;

template <class T> T eps()
{
    return std::numeric_limits<T>::epsilon();
}

// Forward error bound of p' = N p: |fl(N p) - N p| <= c eps |N| |p|.
template <class T> Vec4<T> productBound(const Mat4<T>& n, const Vec4<T>& p, T units)
{
    return (units * eps<T>()) * (n.cwiseAbs() * p.cwiseAbs());
}

class SpecGenerator {
public:
    explicit SpecGenerator(unsigned seed) : rng_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

    Vec3<double> direction()
    {
        std::normal_distribution<double> normal;
        Vec3<double> v;
        do
            v = {normal(rng_), normal(rng_), normal(rng_)};
        while (v.norm() < 1e-3);
        return v.normalized() * uniform(0.5, 4.0);
    }

    foley::ViewSpec<double> foleySpec(foley::Projection projection)
    {
        foley::ViewSpec<double> spec;
        spec.projection = projection;
        spec.vrp = {uniform(-20, 20), uniform(-20, 20), uniform(-20, 20)};
        spec.vpn = direction();
        do
            spec.vup = direction();
        while (angleBetweenLines(spec.vup, spec.vpn) < 0.2);
        const double umin = uniform(-10, 10), vmin = uniform(-10, 10);
        spec.window = {umin, umin + uniform(0.5, 20), vmin, vmin + uniform(0.5, 20)};
        spec.front = uniform(-10, 10);
        spec.back = spec.front - uniform(0.5, 30);
        if (projection == foley::Projection::Perspective)
            spec.prp = {uniform(-15, 15), uniform(-15, 15), spec.front + uniform(0.5, 40)};
        else
            spec.prp = {uniform(-15, 15), uniform(-15, 15), (uniform(0, 1) < 0.5 ? -1 : 1) * uniform(0.5, 40)};
        return spec;
    }

    gl::Camera<double> glCamera(int kind)
    {
        gl::Camera<double> camera;
        camera.lookAt.eye = {uniform(-20, 20), uniform(-20, 20), uniform(-20, 20)};
        camera.lookAt.center = camera.lookAt.eye + direction();
        do
            camera.lookAt.up = direction();
        while (angleBetweenLines(camera.lookAt.up, Vec3<double>(camera.lookAt.center - camera.lookAt.eye)) < 0.2);
        const double l = uniform(-10, 10), b = uniform(-10, 10);
        const double r = l + uniform(0.5, 20), t = b + uniform(0.5, 20);
        const double n = uniform(0.1, 10), f = n + uniform(0.5, 100);
        if (kind == 0)
            camera.projection = gl::Frustum<double>{l, r, b, t, n, f};
        else if (kind == 1)
            camera.projection = gl::Ortho<double>{l, r, b, t, uniform(-10, 10), uniform(-10, 10) + 25};
        else
            camera.projection = gl::Perspective<double>{uniform(1, 170), uniform(0.2, 5), n, f};
        return camera;
    }

private:
    std::mt19937_64 rng_;
};

// Expects an InputError naming `field` with a reason containing `reasonPart`.
template <class F> void expectRefused(F&& f, const std::string& field, const std::string& reasonPart)
{
    try {
        f();
        ADD_FAILURE() << "expected an InputError for " << field;
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), field) << e.what();
        EXPECT_NE(e.reason().find(reasonPart), std::string::npos) << "reason: " << e.reason();
    }
}

} // namespace viewpipe::test
