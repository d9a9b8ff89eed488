#pragma once

// The classical projections of the lecture notes (seed 001) as Foley view
// specifications, and the converse: naming the classical projection that a
// view realizes. Everything stays on the one normalizing pipeline.
//
// Conventions: world y is up. Parallel views have the PRP on the far side of
// the view plane from the object's back, at distance `distance` along VPN.
// Foreshortening of a principal axis is the length its unit vector has in
// the projection; a view plane with unit normal n foreshortens axis i by
// sqrt(1 - n_i^2) in an orthographic view, so the three squares sum to 2.
// An oblique view keeps the faces parallel to the view plane true and draws
// the receding axis at `receding` times its length, at `angleDegrees` on the
// sheet; its projectors meet the plane at alpha = atan(1 / receding)
// (cavalier: 1, 45 deg; cabinet: 1/2, 63.43 deg).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "viewpipe/pipeline.hpp"

namespace viewpipe {

enum class ClassicalKind {
    Front, Top, Side,                      // multiview orthographic
    Isometric, Dimetric, Trimetric,        // axonometric
    Cavalier, Cabinet, Oblique,            // oblique
    OnePoint, TwoPoint, ThreePoint         // perspective
};

struct ClassicalParameters {
    // Axonometric: the view direction by rotation angles, about y (azimuth)
    // then about x (elevation): isometric is (45, 35.26) and takes none;
    // dimetric keeps azimuth 45 (x and z alike) and takes the elevation
    // (default 20); trimetric takes both (default 30, 25).
    std::optional<double> azimuthDegrees, elevationDegrees;
    // Or by foreshortening ratios of x, y, z (each in (0, 1], squares summing to 2).
    std::optional<std::array<double, 3>> foreshortening;
    // Oblique (general): the receding axis's drawn length factor and its angle on the sheet.
    double receding = 1;
    double angleDegrees = 45;
};

// The kinds' names as the CLI and the presets spell them ("front", "isometric", "cabinet", "two-point", ...).
std::string classicalName(ClassicalKind kind);
std::optional<ClassicalKind> classicalKindNamed(const std::string& name);
const std::vector<ClassicalKind>& allClassicalKinds();

// The view that realizes a kind for objects inside an axis-aligned box. The
// parameters apply where the kind takes them (the defaults give the textbook
// cases: isometric, dimetric with two ratios equal, cavalier, cabinet).
foley::ViewSpec<double> classicalView(ClassicalKind kind, const Vec3<double>& boxMin, const Vec3<double>& boxMax,
                                      const ClassicalParameters& parameters = {});

struct VanishingPoint {
    int axis = 0;                 // 0, 1, 2: x, y, z
    Vec3<double> world;           // on the view plane, world coordinates
    Vec3<double> image;           // after the normalizing transformation and the divide (x, y: the picture)
};

struct Classification {
    ProjectionKind projection = ProjectionKind::Parallel; // Parallel or Perspective
    std::string family;           // "multiview orthographic", "axonometric", "oblique", "perspective"
    std::string kind;             // "front", "isometric", "cabinet", "two-point", "general", ...
    std::string description;      // e.g. "parallel, oblique, cabinet (alpha = 63.43 deg)"
    std::optional<std::array<double, 3>> foreshortening; // parallel views: x, y, z
    std::optional<double> alphaDegrees;                  // oblique: projectors against the plane
    std::vector<VanishingPoint> vanishingPoints;         // perspective: the finite ones of x, y, z
};

// Names the classical projection a camera realizes (relative tolerance 1e-9).
Classification classify(const CameraSpec<double>& camera);

// The vanishing point of a world direction (a point at infinity through the
// projection), if finite: absent when the direction is parallel to the view plane.
std::optional<VanishingPoint> vanishingPoint(const CameraSpec<double>& camera, int axis);

} // namespace viewpipe
