// In-between matrices for the stepper's animation.

#include "support.hpp"
#include "viewpipe/animation.hpp"

namespace viewpipe {
namespace {

TEST(Animation, RotationStageTurnsInsteadOfBlending)
{
    const Mat3<double> r = Eigen::AngleAxis<double>(2.5, Vec3<double>(1, 2, 3).normalized()).toRotationMatrix();
    const Mat4<double> stage = embedLinear(r);
    ASSERT_TRUE(isRotation(stage));
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const Mat3<double> m = interpolateStage(stage, t).topLeftCorner<3, 3>();
        EXPECT_TRUE((m * m.transpose()).isIdentity(1e-12)) << t;
        EXPECT_NEAR(m.determinant(), 1, 1e-12);
        // The turn so far is t times the whole angle.
        EXPECT_NEAR(Eigen::AngleAxis<double>(m).angle(), 2.5 * t, 1e-12) << t;
    }
    // A linear blend halfway would shrink: the reason for the slerp, which is not that blend.
    const Mat3<double> blended = 0.5 * (Mat3<double>::Identity() + r);
    EXPECT_LT(blended.determinant(), 0.5);
    const Mat3<double> halfway = interpolateStage(stage, 0.5).topLeftCorner<3, 3>();
    EXPECT_FALSE(halfway.isApprox(blended, 1e-3));
}

TEST(Animation, OtherStagesBlendLinearlyFromTheIdentity)
{
    const Mat4<double> shear = shearXYbyZ(0.5, -0.25);
    EXPECT_FALSE(isRotation(shear));
    EXPECT_TRUE(interpolateStage(shear, 0.0).isIdentity());
    EXPECT_TRUE(interpolateStage(shear, 1.0).isApprox(shear));
    EXPECT_DOUBLE_EQ(interpolateStage(shear, 0.5)(0, 2), 0.25);
    EXPECT_FALSE(isRotation(translation<double>({1, 0, 0})));
}

TEST(Animation, CumulativeAtWholePositionsIsTheStageProduct)
{
    foley::ViewSpec<double> spec{foley::Projection::Perspective, {1, 2, 3}, {1, 1, 1}, {0, 1, 0}, {2, 1, 30},
                                 {-5, 5, -4, 6}, 10, -20};
    const std::vector<Stage<double>> stages = foley::stages(spec);
    const std::vector<Mat4<double>> products = cumulativeProducts(stages);
    EXPECT_TRUE(cumulativeAt(stages, 0).isIdentity());
    for (std::size_t k = 1; k <= stages.size(); ++k)
        EXPECT_TRUE(cumulativeAt(stages, double(k)).isApprox(products[k - 1], 1e-14)) << k;
    EXPECT_TRUE(cumulativeAt(stages, 99).isApprox(products.back(), 1e-14)); // clamped
    // Halfway through R (stage 2) the rotation part is still a rotation.
    const Mat3<double> half = (cumulativeAt(stages, 1.5) * translation<double>(spec.vrp)).topLeftCorner<3, 3>();
    EXPECT_TRUE((half * half.transpose()).isIdentity(1e-12));
}

} // namespace
} // namespace viewpipe
