#pragma once

// In-between matrices for animating one stage: from the identity (t = 0) to
// the stage's matrix (t = 1). A rotation turns (quaternion slerp) instead of
// blending entries, which would shrink and skew what it moves; translations,
// shears, scales and the perspective matrix blend linearly.

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "viewpipe/stage.hpp"

namespace viewpipe {

template <class T> bool isRotation(const Mat4<T>& m)
{
    const Mat3<T> r = m.template topLeftCorner<3, 3>();
    const T tolerance = T(64) * epsilonOf<T>();
    return m.template topRightCorner<3, 1>().isZero(T(0)) && m.template bottomLeftCorner<1, 3>().isZero(T(0)) &&
           m(3, 3) == T(1) && (r * r.transpose()).isIdentity(tolerance) && r.determinant() > T(0);
}

template <class T> Mat4<T> interpolateStage(const Mat4<T>& stage, T t)
{
    if (isRotation(stage)) {
        const Eigen::Quaternion<T> end(Mat3<T>(stage.template topLeftCorner<3, 3>()));
        const Eigen::Quaternion<T> now = Eigen::Quaternion<T>::Identity().slerp(t, end);
        return embedLinear(now.toRotationMatrix());
    }
    return Mat4<T>::Identity() + t * (stage - Mat4<T>::Identity());
}

// The cumulative matrix at a continuous position along the stages: 0 is the
// world (identity), k is after stage k, and k + t is stage k+1 in progress.
// Pictures draw each point it gives divided by its w, whether or not the
// pipeline has a divide stage: a stage that makes w differ from 1 is pictured
// by what it means (P_depth as the canonical cube), and a divide stage, no
// matrix, leaves the picture as it was.
template <class T> Mat4<T> cumulativeAt(const std::vector<Stage<T>>& stages, double position)
{
    const double clamped = std::clamp(position, 0.0, double(stages.size()));
    const std::size_t whole = static_cast<std::size_t>(std::floor(clamped));
    Mat4<T> m = Mat4<T>::Identity();
    for (std::size_t k = 0; k < whole; ++k)
        m = stages[k].matrix * m;
    const double t = clamped - double(whole);
    if (whole < stages.size() && t > 0)
        m = interpolateStage(stages[whole].matrix, T(t)) * m;
    return m;
}

// Whether a stage keeps lengths and angles (translations, rotations, their
// products): pictures of the stages it joins share one framing, so that they
// show what it moved instead of following it. Not the divide: it changes no
// picture, but framed with P_depth the app kept P_depth's camera under the
// divide's shorter caption, and its legend covered the cube.
template <class T> bool keepsShape(const Stage<T>& stage)
{
    const Mat4<T>& m = stage.matrix;
    const Mat3<T> r = m.template topLeftCorner<3, 3>();
    return !stage.divides() && m.template bottomLeftCorner<1, 3>().isZero(T(0)) && m(3, 3) == T(1) &&
           (r * r.transpose()).isIdentity(T(64) * epsilonOf<T>());
}

// The stages pictured with one framing together with stage k (0 being the
// world): from the last one that changed shapes up to the next one.
template <class T> std::pair<int, int> framedTogether(const std::vector<Stage<T>>& stages, int k)
{
    int first = k, last = k;
    while (first > 0 && keepsShape(stages[std::size_t(first - 1)]))
        --first;
    while (last < int(stages.size()) && keepsShape(stages[std::size_t(last)]))
        ++last;
    return {first, last};
}

// The matrix of a faint ghost that pictures of stage k show: the stage
// before, after a translation or rotation that moves something, so that a
// student sees where things came from. None after other stages.
template <class T> std::optional<Mat4<T>> ghostAt(const std::vector<Stage<T>>& stages, int k)
{
    if (k <= 0 || k > int(stages.size()))
        return std::nullopt;
    const Stage<T>& stage = stages[std::size_t(k - 1)];
    if (!keepsShape(stage) || stage.matrix.isIdentity(T(0)))
        return std::nullopt;
    return cumulativeAt(stages, double(k - 1));
}

} // namespace viewpipe
