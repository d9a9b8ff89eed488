// The camera as code in five dialects (see code.hpp). Each dialect writes the
// library calls closest to the camera; where they cannot say everything (the
// API's clip space, a left-handed eye, an infinite far plane) it writes the
// exact extra matrix with a comment saying why. The reverse, applyCode, reads
// the calls back with a small expression reader.

#include "viewpipe/report/code.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <regex>

#include "viewpipe/error.hpp"
#include "viewpipe/format.hpp"

namespace viewpipe::report
{
namespace
{

using Camera = gl::Camera<double>;
using Mat4d = Mat4<double>;

const std::string kLookAtField = "camera.look_at.";

struct DialectNames {
    Dialect dialect;
    const char* name;
    const char* title;
};

constexpr DialectNames kDialectNames[] = {{Dialect::OpenGL, "opengl", "Legacy OpenGL"},
                                          {Dialect::Glm, "glm", "glm"},
                                          {Dialect::DirectXMath, "directxmath", "DirectXMath"},
                                          {Dialect::ThreeJs, "threejs", "three.js"},
                                          {Dialect::WgpuMatrix, "wgpu-matrix", "wgpu-matrix"}};

const DialectNames& namesOf(Dialect dialect)
{
    for (const DialectNames& names : kDialectNames)
        if (names.dialect == dialect)
            return names;
    throw std::logic_error("unknown dialect");
}

// ---------------------------------------------------------------------------
// Fields

const std::map<std::string, std::string> kProjectionTooltips = {
    {"fovy_deg", "fovy: the vertical field of view, in degrees"},
    {"aspect", "aspect: the view's width / height, a ratio"},
    {"near", "near: the distance from the eye to the near plane, in world units"},
    {"far", "far: the distance from the eye to the far plane, in world units"},
    {"left", "left: x of the view volume's left side (a frustum's on the near plane), in eye coordinates"},
    {"right", "right: x of the view volume's right side (a frustum's on the near plane), in eye coordinates"},
    {"bottom", "bottom: y of the view volume's bottom side (a frustum's on the near plane), in eye coordinates"},
    {"top", "top: y of the view volume's top side (a frustum's on the near plane), in eye coordinates"},
};

const std::map<std::string, std::string> kLookAtTooltips = {
    {"eye", "where the eye is, in world coordinates"},
    {"center", "the point looked at, in world coordinates"},
    {"up", "the up direction, in world coordinates (only its direction counts)"},
};

std::string lookAtField(const std::string& vector, int axis)
{
    return kLookAtField + vector + "[" + std::to_string(axis) + "]";
}

std::string tooltipOf(const std::string& field)
{
    if (field.compare(0, gl::kProjectionField.size(), gl::kProjectionField) == 0)
        return kProjectionTooltips.at(field.substr(gl::kProjectionField.size()));
    const std::string vector = field.substr(kLookAtField.size(), field.find('[') - kLookAtField.size());
    return vector + " " + "xyz"[field[field.size() - 2] - '0'] + ": " + kLookAtTooltips.at(vector);
}

// One number of a call: the camera field it stands for and its value.
struct Arg {
    std::string field;
    double value;
};

Arg projectionArg(const std::string& name, double value)
{
    return {gl::kProjectionField + name, value};
}

double farOf(const gl::ProjectionSpec<double>& spec)
{
    return std::visit([](const auto& p) { return p.zFar; }, spec);
}

// The projection's numbers in a call's order: fovy, aspect, near, far or the
// box (left, right, bottom, top or three.js's left, right, top, bottom), near, far.
std::vector<Arg> projectionArgs(const gl::ProjectionSpec<double>& spec, bool topBeforeBottom, bool swapNearFar)
{
    std::vector<Arg> args;
    double zNear = 0, zFar = 0;
    std::visit(
        [&](const auto& p) {
            using P = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<P, gl::Perspective<double>>) {
                args = {projectionArg("fovy_deg", p.fovyDegrees), projectionArg("aspect", p.aspect)};
            } else {
                args = {projectionArg("left", p.left), projectionArg("right", p.right)};
                const Arg bottom = projectionArg("bottom", p.bottom), top = projectionArg("top", p.top);
                args.push_back(topBeforeBottom ? top : bottom);
                args.push_back(topBeforeBottom ? bottom : top);
            }
            zNear = p.zNear;
            zFar = p.zFar;
        },
        spec);
    args.push_back(projectionArg(swapNearFar ? "far" : "near", swapNearFar ? zFar : zNear));
    args.push_back(projectionArg(swapNearFar ? "near" : "far", swapNearFar ? zNear : zFar));
    return args;
}

// ---------------------------------------------------------------------------
// What each dialect can say, and the plan for a camera

enum class InfinitePerspective { None, MinusOneToOne, ZeroToOne };

struct Abilities {
    bool zeroToOne;       // its projections' depth range is [0, 1] (else OpenGL's [-1, 1])
    bool bothDepthRanges; // it has both (glm's _ZO and _NO)
    bool handedCalls;     // it has left-handed calls (glm's and DirectXMath's *LH)
    bool swapReverses;    // near and far exchanged in its perspective and ortho calls reverse depth
    bool reverseZCalls;   // it has reversed-depth perspective and frustum calls that take far = infinity
    InfinitePerspective infinitePerspective;
};

Abilities abilitiesOf(Dialect dialect)
{
    switch (dialect) {
    case Dialect::OpenGL: return {false, false, false, true, false, InfinitePerspective::None};
    case Dialect::Glm: return {false, true, true, true, false, InfinitePerspective::MinusOneToOne};
    case Dialect::DirectXMath: return {true, false, true, true, false, InfinitePerspective::None};
    case Dialect::ThreeJs: return {false, false, false, false, false, InfinitePerspective::None};
    case Dialect::WgpuMatrix: return {true, false, false, true, true, InfinitePerspective::ZeroToOne};
    }
    throw std::logic_error("unknown dialect");
}

// How the camera is written: what the call (or the written-out matrix) does,
// and the exact rest on the clip side and on the eye side.
struct Plan {
    bool explicitLimit = false; // far = infinity that no call takes: OpenGL's limit written out
    bool zeroToOne = false;     // the depth range of what is written
    bool reversed = false;      // what is written reverses depth already
    bool swapNearFar = false;   // ... by near and far exchanged in the call
    bool leftHanded = false;    // what is written mirrors z already (a *LH call)
    Mat4d clipConversion;       // the API's clip coordinates from what is written
    bool mirrorEye = false;     // z still to mirror on the eye side (a left-handed camera)
    bool convertsClip() const { return !clipConversion.isIdentity(0); }
};

Mat4d writtenNdc(bool zeroToOne, bool reversed)
{
    return gl::ndcConversion<double>(zeroToOne ? gl::Api::Direct3D : gl::Api::OpenGL,
                                     reversed ? gl::DepthMode::Reversed : gl::DepthMode::Standard);
}

Plan planFor(const Camera& camera, Dialect dialect)
{
    const Abilities can = abilitiesOf(dialect);
    const bool reversed = camera.depth == gl::DepthMode::Reversed;
    const bool ortho = std::holds_alternative<gl::Ortho<double>>(camera.projection);
    const bool perspective = std::holds_alternative<gl::Perspective<double>>(camera.projection);
    const bool frustum = std::holds_alternative<gl::Frustum<double>>(camera.projection);
    Plan plan;
    plan.zeroToOne = can.bothDepthRanges ? gl::zeroToOneDepth(camera.api) : can.zeroToOne;
    // glm 0.9.9's frustumLH_* has the wrong sign in its off-center terms (g-truc/glm#982, fixed in
    // #1080 for 1.0): its right-handed frustum with z mirrored is exact in every version.
    const bool handedCall = can.handedCalls && !(dialect == Dialect::Glm && frustum);
    plan.leftHanded = handedCall && camera.handedness == gl::Handedness::Left;
    if (reversed && can.reverseZCalls && !ortho) {
        plan.reversed = true;
    } else if (std::isinf(farOf(camera.projection))) {
        if (perspective && can.infinitePerspective != InfinitePerspective::None) {
            plan.zeroToOne = can.infinitePerspective == InfinitePerspective::ZeroToOne;
        } else {
            plan.explicitLimit = true;
            plan.zeroToOne = plan.leftHanded = false;
        }
    } else if (reversed && can.swapReverses && !frustum) {
        plan.reversed = plan.swapNearFar = true;
    }
    // The ranges' maps are exact in binary (entries 0, +-1, +-1/2, 2), and so is this product.
    plan.clipConversion =
        gl::ndcConversion<double>(camera.api, camera.depth) * writtenNdc(plan.zeroToOne, plan.reversed).inverse();
    plan.mirrorEye = camera.handedness == gl::Handedness::Left && !plan.leftHanded;
    return plan;
}

std::string depthRangeText(bool zeroToOne, bool reversed)
{
    return std::string("depth ") + (zeroToOne ? "[0, 1]" : "[-1, 1]") +
           (reversed ? (zeroToOne ? " reversed (near -> 1, far -> 0)" : " reversed (near -> 1, far -> -1)") : "");
}

// ---------------------------------------------------------------------------
// Writing

// How a dialect spells numbers and matrices.
struct Spelling {
    bool cppFloat = false;                   // C++ float literals: 40.0f
    std::string degreesBefore, degreesAfter; // around fovy's degrees in a projection call
    std::string constant;                    // declares constants: "const float "
    std::string cotHalfFovy;                 // cot(fovy / 2) of a constant `fovy` in degrees
    bool rowByRow = false;                   // matrix literals row by row (three.js's Matrix4.set)
};

std::string literal(const Spelling& spelling, double x)
{
    if (std::isinf(x))
        return "Infinity"; // wgpu-matrix's far: the only call that takes it
    std::string digits = formatShortest(x);
    if (spelling.cppFloat && digits.find_first_of(".e") == std::string::npos)
        digits += ".0";
    return digits;
}

class CodeWriter
{
public:
    explicit CodeWriter(Spelling spelling) : spelling_(std::move(spelling)) {}

    CodeWriter& operator<<(const std::string& text)
    {
        code_.text += text;
        return *this;
    }

    // A camera number, its characters recorded (a C++ float's 'f' left out); fovy
    // as a call's argument converted to radians where the call takes radians.
    CodeWriter& number(const Arg& arg, bool callArgument = true)
    {
        const bool degrees = callArgument && arg.field == gl::kProjectionField + "fovy_deg";
        const std::string digits = literal(spelling_, arg.value);
        code_.text += degrees ? spelling_.degreesBefore : "";
        code_.numbers.push_back({code_.text.size(), digits.size(), arg.field, arg.value, tooltipOf(arg.field)});
        code_.text += digits;
        if (spelling_.cppFloat)
            code_.text += "f";
        code_.text += degrees ? spelling_.degreesAfter : "";
        return *this;
    }

    CodeWriter& numbers(const std::vector<Arg>& args)
    {
        for (std::size_t i = 0; i < args.size(); ++i)
            number(args[i]) << (i + 1 < args.size() ? ", " : "");
        return *this;
    }

    CodeWriter& vector(const Camera& camera, const std::string& name, const std::string& before,
                       const std::string& after)
    {
        const gl::LookAt<double>& look = camera.lookAt;
        const Vec3<double>& v = name == "eye" ? look.eye : name == "center" ? look.center : look.up;
        *this << before;
        numbers({{lookAtField(name, 0), v.x()}, {lookAtField(name, 1), v.y()}, {lookAtField(name, 2), v.z()}});
        return *this << after;
    }

    // A matrix literal's 16 entries, column by column (row by row for three.js).
    CodeWriter& matrix(const std::array<std::array<std::string, 4>, 4>& rows)
    {
        for (int i = 0; i < 16; ++i) {
            const int major = i / 4, minor = i % 4;
            *this << (spelling_.rowByRow ? rows[major][minor] : rows[minor][major])
                  << (i == 15      ? ""
                      : minor == 3 ? ",  "
                                   : ", ");
        }
        return *this;
    }

    CodeWriter& matrix(const Mat4d& m)
    {
        std::array<std::array<std::string, 4>, 4> rows;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                rows[r][c] = m(r, c) == std::round(m(r, c))
                                 ? formatShortest(m(r, c))
                                 : literal(spelling_, m(r, c)) + (spelling_.cppFloat ? "f" : "");
        return matrix(rows);
    }

    const Spelling& spelling() const { return spelling_; }
    CameraCode take() { return std::move(code_); }

private:
    Spelling spelling_;
    CameraCode code_;
};

// OpenGL's projection in the limit far -> infinity, its constants declared
// first (their numbers recorded); returns the matrix's entries.
std::array<std::array<std::string, 4>, 4> writeInfiniteLimit(CodeWriter& out, const Camera& camera,
                                                             const std::string& callName)
{
    std::array<std::array<std::string, 4>, 4> rows;
    for (auto& row : rows)
        row.fill("0");
    rows[2][2] = "-1";
    rows[2][3] = "-2 * zNear";
    rows[3][2] = "-1";
    const Spelling& spelling = out.spelling();
    out << "// " << callName << " can't take far = infinity. OpenGL's limit as far -> infinity (depth [-1, 1]),\n"
        << "// written out; the API's own depth range follows from it below.\n"
        << spelling.constant;
    const std::vector<Arg> args = projectionArgs(camera.projection, false, false);
    const std::vector<std::string> names = std::holds_alternative<gl::Perspective<double>>(camera.projection)
                                               ? std::vector<std::string>{"fovy", "aspect", "zNear"}
                                               : std::vector<std::string>{"left", "right", "bottom", "top", "zNear"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        out << names[i] << " = ";
        // A declared fovy stays in degrees: the cot expression converts it.
        out.number(args[i], false) << (i + 1 < names.size() ? ", " : "; // far = infinity\n");
    }
    if (names.size() == 3) {
        out << spelling.constant << "f = " << spelling.cotHalfFovy << ";\n";
        rows[0][0] = "f / aspect";
        rows[1][1] = "f";
    } else {
        rows[0][0] = "2 * zNear / (right - left)";
        rows[0][2] = "(right + left) / (right - left)";
        rows[1][1] = "2 * zNear / (top - bottom)";
        rows[1][2] = "(top + bottom) / (top - bottom)";
    }
    return rows;
}

std::string conventionsComment(const Camera& camera)
{
    return "// " + gl::apiTitle(camera.api) + ", " +
           (camera.handedness == gl::Handedness::Left ? "left-handed (the eye looks down +z)"
                                                      : "right-handed (the eye looks down -z)") +
           ", " + depthRangeText(gl::zeroToOneDepth(camera.api), camera.depth == gl::DepthMode::Reversed) +
           (gl::yDown(camera.api) ? ", clip y down" : "") + ".\n";
}

std::string clipConversionComment(const Camera& camera, const Plan& plan)
{
    return "// To " + gl::apiTitle(camera.api) + "'s clip coordinates (" +
           depthRangeText(gl::zeroToOneDepth(camera.api), camera.depth == gl::DepthMode::Reversed) +
           (gl::yDown(camera.api) ? ", y down" : "") + ") from the call's (" +
           depthRangeText(plan.zeroToOne, plan.reversed) + "): one exact linear map.\n";
}

const std::string kSwapComment = "// Reversed depth: near and far exchanged in the call.\n";
const std::string kMirrorEyeComment =
    "// Left-handed: the eye looks down +z, so z is mirrored before the right-handed projection.\n";

std::string handSuffix(const Camera& camera)
{
    return camera.handedness == gl::Handedness::Left ? "LH" : "RH";
}

// Legacy OpenGL: each call multiplies the current matrix on the right, so
// what acts last on clip coordinates comes first.
void writeOpenGL(CodeWriter& out, const Camera& camera, const Plan& plan)
{
    out << "// Legacy OpenGL: column vectors (p' = M p); each call multiplies the current matrix on the right.\n"
        << "glMatrixMode(GL_PROJECTION);\nglLoadIdentity();\n";
    if (plan.convertsClip()) {
        if (gl::zeroToOneDepth(camera.api))
            out << "// OpenGL clips z to [-w, w]: for depth in [0, 1] call glClipControl("
                << (gl::yDown(camera.api) ? "GL_UPPER_LEFT" : "GL_LOWER_LEFT") << ",\n"
                << "// GL_ZERO_TO_ONE) (OpenGL 4.5) as well, or near objects are clipped as if at depth -1"
                << (gl::yDown(camera.api) ? ";\n// GL_UPPER_LEFT takes the y this matrix negates back to OpenGL's window y" : "")
                << ".\n";
        out << clipConversionComment(camera, plan) << "const GLdouble clipConversion[16] = {";
        out.matrix(plan.clipConversion) << "}; // column by column\nglMultMatrixd(clipConversion);\n";
    }
    if (plan.explicitLimit) {
        const bool perspective = std::holds_alternative<gl::Perspective<double>>(camera.projection);
        const auto rows = writeInfiniteLimit(out, camera, perspective ? "gluPerspective" : "glFrustum");
        out << "const GLdouble infiniteFar[16] = {";
        out.matrix(rows) << "}; // column by column\nglMultMatrixd(infiniteFar);\n";
    } else {
        const char* call = std::visit(
            [](const auto& p) {
                using P = std::decay_t<decltype(p)>;
                return std::is_same_v<P, gl::Perspective<double>> ? "gluPerspective"
                       : std::is_same_v<P, gl::Frustum<double>>   ? "glFrustum"
                                                                  : "glOrtho";
            },
            camera.projection);
        out << (plan.swapNearFar ? kSwapComment : "") << call << "(";
        out.numbers(projectionArgs(camera.projection, false, plan.swapNearFar)) << ");\n";
    }
    if (plan.mirrorEye)
        out << kMirrorEyeComment << "glScaled(1, 1, -1);\n";
    out << "glMatrixMode(GL_MODELVIEW);\nglLoadIdentity();\n";
    if (camera.handedness == gl::Handedness::Left)
        out << "// Left-handed view (lookAtLH): gluLookAt's rows s, u, -f become -s, u, f.\nglScaled(-1, 1, -1);\n";
    out << "gluLookAt(";
    out.vector(camera, "eye", "", ", ").vector(camera, "center", "", ", ").vector(camera, "up", "", ");\n");
}

std::string glmCall(const Camera& camera, const Plan& plan)
{
    const std::string hand = plan.leftHanded ? "LH" : "RH", range = plan.zeroToOne ? "_ZO" : "_NO";
    return std::visit(
        [&](const auto& p) -> std::string {
            using P = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<P, gl::Perspective<double>>)
                return std::isinf(p.zFar) ? "glm::infinitePerspective" + hand : "glm::perspective" + hand + range;
            else if constexpr (std::is_same_v<P, gl::Frustum<double>>)
                return "glm::frustum" + hand + range;
            else
                return "glm::ortho" + hand + range;
        },
        camera.projection);
}

void writeGlm(CodeWriter& out, const Camera& camera, const Plan& plan)
{
    out << "// glm: column vectors (p' = M p), m[column][row].\n"
        << "#include <glm/glm.hpp>\n#include <glm/gtc/matrix_transform.hpp>\n\n"
        << "glm::mat4 view = glm::lookAt" << handSuffix(camera) << "(";
    out.vector(camera, "eye", "glm::vec3(", "), ")
        .vector(camera, "center", "glm::vec3(", "), ")
        .vector(camera, "up", "glm::vec3(", "));\n");
    if (plan.explicitLimit) {
        const auto rows = writeInfiniteLimit(out, camera, "glm::frustum");
        out << "glm::mat4 proj(";
        out.matrix(rows) << "); // column by column\n";
    } else {
        std::vector<Arg> args = projectionArgs(camera.projection, false, plan.swapNearFar);
        if (std::isinf(farOf(camera.projection)))
            args.pop_back(); // glm::infinitePerspective* take no far
        out << (plan.swapNearFar ? kSwapComment : "") << "glm::mat4 proj = " << glmCall(camera, plan) << "(";
        out.numbers(args) << ");\n";
    }
    if (plan.mirrorEye)
        out << kMirrorEyeComment << "proj = glm::scale(proj, glm::vec3(1.0f, 1.0f, -1.0f));\n";
    const Mat4d yFlip = Vec4<double>(1, -1, 1, 1).asDiagonal();
    if (plan.clipConversion == yFlip && !plan.explicitLimit) {
        // The Vulkan idiom: negate row 1, whose nonzero entries depend on the kind.
        out << "// Vulkan's clip y points down: negate row 1.\nproj[1][1] *= -1.0f;\n";
        if (std::holds_alternative<gl::Frustum<double>>(camera.projection))
            out << "proj[2][1] *= -1.0f;\n";
        if (std::holds_alternative<gl::Ortho<double>>(camera.projection))
            out << "proj[3][1] *= -1.0f;\n";
    } else if (plan.convertsClip()) {
        out << clipConversionComment(camera, plan) << "proj = glm::mat4(";
        out.matrix(plan.clipConversion) << ") * proj;\n";
    }
}

void writeDirectXMath(CodeWriter& out, const Camera& camera, const Plan& plan)
{
    out << "// DirectXMath: row vectors (p' = p * M), so each matrix is the transpose of ViewPipe's\n"
        << "// column-vector one; depth in [0, 1].\n#include <DirectXMath.h>\n"
        << (plan.explicitLimit ? "#include <cmath>\n" : "") << "using namespace DirectX;\n\n"
        << "XMMATRIX view = XMMatrixLookAt" << handSuffix(camera) << "(";
    out.vector(camera, "eye", "XMVectorSet(", ", 0.0f), ")
        .vector(camera, "center", "XMVectorSet(", ", 0.0f), ")
        .vector(camera, "up", "XMVectorSet(", ", 0.0f));\n");
    if (plan.explicitLimit) {
        const auto rows = writeInfiniteLimit(out, camera,
                                             std::holds_alternative<gl::Perspective<double>>(camera.projection)
                                                 ? "XMMatrixPerspectiveFov*"
                                                 : "XMMatrixPerspectiveOffCenter*");
        // Its rows are ViewPipe's columns, the order `matrix` writes.
        out << "XMMATRIX proj(";
        out.matrix(rows) << ");\n";
    } else {
        const std::string call = std::visit(
            [](const auto& p) -> std::string {
                using P = std::decay_t<decltype(p)>;
                return std::is_same_v<P, gl::Perspective<double>> ? "XMMatrixPerspectiveFov"
                       : std::is_same_v<P, gl::Frustum<double>>   ? "XMMatrixPerspectiveOffCenter"
                                                                  : "XMMatrixOrthographicOffCenter";
            },
            camera.projection);
        out << (plan.swapNearFar ? kSwapComment : "") << "XMMATRIX proj = " << call << (plan.leftHanded ? "LH" : "RH")
            << "(";
        out.numbers(projectionArgs(camera.projection, false, plan.swapNearFar)) << ");\n";
    }
    if (plan.mirrorEye)
        out << kMirrorEyeComment << "proj = XMMatrixMultiply(XMMatrixScaling(1.0f, 1.0f, -1.0f), proj);\n";
    if (plan.convertsClip()) {
        // Row vectors: the conversion acts last, on the right, transposed (the order `matrix` writes).
        out << clipConversionComment(camera, plan) << "proj = XMMatrixMultiply(proj, XMMATRIX(";
        out.matrix(plan.clipConversion) << "));\n";
    }
}

void writeThreeJs(CodeWriter& out, const Camera& camera, const Plan& plan)
{
    out << "// three.js: column vectors (p' = M p); the view is camera.matrixWorldInverse.\n"
        << "import * as THREE from 'three';\n\n";
    const bool perspective = std::holds_alternative<gl::Perspective<double>>(camera.projection);
    const bool ortho = std::holds_alternative<gl::Ortho<double>>(camera.projection);
    const bool setsMatrix = plan.explicitLimit || !(perspective || ortho) || plan.convertsClip() || plan.mirrorEye;
    if (plan.explicitLimit) {
        out << "const camera = new THREE.PerspectiveCamera();\n";
        const auto rows = writeInfiniteLimit(out, camera, perspective ? "THREE.PerspectiveCamera" : "makePerspective");
        out << "camera.projectionMatrix.set(";
        out.matrix(rows) << "); // row by row\n";
    } else if (perspective || ortho) {
        out << (perspective ? "const camera = new THREE.PerspectiveCamera("
                            : "const camera = new THREE.OrthographicCamera(");
        out.numbers(projectionArgs(camera.projection, true, false)) << ");\n";
    } else {
        out << "// A general frustum: the matrix itself (updateProjectionMatrix() would replace it).\n"
            << "const camera = new THREE.PerspectiveCamera();\ncamera.projectionMatrix.makePerspective(";
        out.numbers(projectionArgs(camera.projection, true, false)) << ");\n";
    }
    if (plan.convertsClip()) {
        if (gl::zeroToOneDepth(camera.api))
            out << "// WebGLRenderer clips z to [-w, w]: this matrix is for a renderer whose depth is [0, 1]\n"
                << "// (three.js's WebGPURenderer: camera.coordinateSystem = THREE.WebGPUCoordinateSystem).\n";
        out << clipConversionComment(camera, plan) << "camera.projectionMatrix.premultiply(new THREE.Matrix4().set(";
        out.matrix(plan.clipConversion) << "));\n";
    }
    if (plan.mirrorEye)
        out << kMirrorEyeComment << "camera.projectionMatrix.multiply(new THREE.Matrix4().makeScale(1, 1, -1));\n";
    if (setsMatrix)
        out << "camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();\n";
    out.vector(camera, "eye", "camera.position.set(", ");\n")
        .vector(camera, "up", "camera.up.set(", ");\n")
        .vector(camera, "center", "camera.lookAt(", ");\n");
    if (camera.handedness == gl::Handedness::Left)
        out << "// Left-handed view (lookAtLH): three.js's rows s, u, -f become -s, u, f, as the camera's scale.\n"
            << "camera.scale.set(-1, 1, -1);\n";
    out << "camera.updateMatrixWorld(); // computes camera.matrixWorldInverse\n";
}

void writeWgpuMatrix(CodeWriter& out, const Camera& camera, const Plan& plan)
{
    out << "// wgpu-matrix: column vectors (p' = M p), stored column by column; depth in [0, 1].\n"
        << "import { mat4 } from 'wgpu-matrix';\n\n";
    if (camera.handedness == gl::Handedness::Left) {
        out << "// Left-handed view (lookAtLH): mat4.lookAt's rows s, u, -f become -s, u, f.\n"
            << "const view = mat4.multiply(mat4.scaling([-1, 1, -1]), mat4.lookAt(";
        out.vector(camera, "eye", "[", "], ").vector(camera, "center", "[", "], ").vector(camera, "up", "[", "]));\n");
    } else {
        out << "const view = mat4.lookAt(";
        out.vector(camera, "eye", "[", "], ").vector(camera, "center", "[", "], ").vector(camera, "up", "[", "]);\n");
    }
    const std::string declaration = plan.mirrorEye || plan.convertsClip() ? "let proj = " : "const proj = ";
    if (plan.explicitLimit) {
        const auto rows = writeInfiniteLimit(out, camera, "mat4.frustum");
        out << declaration << "mat4.create(";
        out.matrix(rows) << ");\n";
    } else {
        const bool reverseZ = plan.reversed && !plan.swapNearFar;
        const std::string call = std::visit(
            [&](const auto& p) -> std::string {
                using P = std::decay_t<decltype(p)>;
                const std::string base = std::is_same_v<P, gl::Perspective<double>> ? "mat4.perspective"
                                         : std::is_same_v<P, gl::Frustum<double>>   ? "mat4.frustum"
                                                                                    : "mat4.ortho";
                return base + (reverseZ ? "ReverseZ" : "");
            },
            camera.projection);
        out << (plan.swapNearFar ? kSwapComment : "") << declaration << call << "(";
        out.numbers(projectionArgs(camera.projection, false, plan.swapNearFar)) << ");\n";
    }
    if (plan.mirrorEye)
        out << kMirrorEyeComment << "proj = mat4.scale(proj, [1, 1, -1]);\n";
    if (plan.convertsClip()) {
        out << clipConversionComment(camera, plan) << "proj = mat4.multiply(mat4.create(";
        out.matrix(plan.clipConversion) << "), proj);\n";
    }
}

Spelling spellingOf(Dialect dialect)
{
    Spelling cppFloat;
    cppFloat.cppFloat = true;
    cppFloat.constant = "const float ";
    Spelling javaScript;
    javaScript.constant = "const ";
    javaScript.cotHalfFovy = "1 / Math.tan(fovy * Math.PI / 360)";
    switch (dialect) {
    case Dialect::OpenGL: {
        Spelling gl;
        gl.constant = "const GLdouble ";
        gl.cotHalfFovy = "1 / tan(fovy * M_PI / 360)";
        return gl;
    }
    case Dialect::Glm:
        cppFloat.degreesBefore = "glm::radians(";
        cppFloat.degreesAfter = ")";
        cppFloat.cotHalfFovy = "1.0f / std::tan(glm::radians(fovy) / 2.0f)";
        return cppFloat;
    case Dialect::DirectXMath:
        cppFloat.degreesBefore = "XMConvertToRadians(";
        cppFloat.degreesAfter = ")";
        cppFloat.cotHalfFovy = "1.0f / std::tan(XMConvertToRadians(fovy) / 2.0f)";
        return cppFloat;
    case Dialect::ThreeJs: javaScript.rowByRow = true; return javaScript;
    case Dialect::WgpuMatrix: javaScript.degreesAfter = " * Math.PI / 180"; return javaScript;
    }
    throw std::logic_error("unknown dialect");
}

// ---------------------------------------------------------------------------
// Fields of a camera

std::string kindName(const gl::ProjectionSpec<double>& spec)
{
    return std::visit(
        [](const auto& p) {
            using P = std::decay_t<decltype(p)>;
            return std::is_same_v<P, gl::Perspective<double>> ? "perspective"
                   : std::is_same_v<P, gl::Frustum<double>>   ? "frustum"
                                                              : "ortho";
        },
        spec);
}

// The projection's number called `name` ("fovy_deg", "near", ...), or null when its kind has none.
double* projectionNumber(gl::ProjectionSpec<double>& spec, const std::string& name)
{
    return std::visit(
        [&](auto& p) -> double* {
            using P = std::decay_t<decltype(p)>;
            if (name == "near")
                return &p.zNear;
            if (name == "far")
                return &p.zFar;
            if constexpr (std::is_same_v<P, gl::Perspective<double>>) {
                if (name == "fovy_deg")
                    return &p.fovyDegrees;
                if (name == "aspect")
                    return &p.aspect;
            } else {
                const std::map<std::string, double*> box = {
                    {"left", &p.left}, {"right", &p.right}, {"bottom", &p.bottom}, {"top", &p.top}};
                if (const auto it = box.find(name); it != box.end())
                    return it->second;
            }
            return nullptr;
        },
        spec);
}

void validateCamera(const Camera& camera)
{
    std::visit([](const auto& p) { gl::validate(p); }, camera.projection);
    gl::eyeBasis(camera.lookAt);
}

// ---------------------------------------------------------------------------
// Reading pasted code

constexpr double kPi = 3.14159265358979323846;

// A number as written: coefficient * (pi / 180)^angleUnits, so that
// glm::radians(45.0f), XM_PIDIV4 and 45 * Math.PI / 180 read back as 45
// degrees exactly, and 0.785398f as the radians it is.
struct Quantity {
    double coefficient = 0;
    int angleUnits = 0;

    double value() const { return coefficient * std::pow(kPi / 180, angleUnits); }
    double degrees() const { return angleUnits == 1 ? coefficient : value() * 180 / kPi; }
};

Quantity operator*(const Quantity& a, const Quantity& b)
{
    return {a.coefficient * b.coefficient, a.angleUnits + b.angleUnits};
}

Quantity operator/(const Quantity& a, const Quantity& b)
{
    return {a.coefficient / b.coefficient, a.angleUnits - b.angleUnits};
}

Quantity sum(const Quantity& a, const Quantity& b, double sign)
{
    if (a.angleUnits == b.angleUnits)
        return {a.coefficient + sign * b.coefficient, a.angleUnits};
    return {a.value() + sign * b.value(), 0};
}

struct ReadFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Names with a value, in degrees where they are angles.
const std::map<std::string, Quantity> kConstants = {
    {"XM_PI", {180, 1}},         {"XM_2PI", {360, 1}},        {"XM_PIDIV2", {90, 1}},
    {"XM_PIDIV4", {45, 1}},      {"M_PI", {180, 1}},          {"M_PI_2", {90, 1}},
    {"M_PI_4", {45, 1}},         {"Math.PI", {180, 1}},       {"glm::pi", {180, 1}},
    {"glm::two_pi", {360, 1}},   {"glm::half_pi", {90, 1}},   {"glm::quarter_pi", {45, 1}},
    {"Infinity", {INFINITY, 0}}, {"INFINITY", {INFINITY, 0}}, {"Number.POSITIVE_INFINITY", {INFINITY, 0}},
};

enum class NameKind { Radians, Identity, Vector, VectorWithW };

const std::map<std::string, NameKind> kFunctions = {
    {"glm::radians", NameKind::Radians},
    {"radians", NameKind::Radians},
    {"XMConvertToRadians", NameKind::Radians},
    {"THREE.MathUtils.degToRad", NameKind::Radians},
    {"MathUtils.degToRad", NameKind::Radians},
    {"utils.degToRad", NameKind::Radians},
    {"float", NameKind::Identity},
    {"double", NameKind::Identity},
    {"GLfloat", NameKind::Identity},
    {"GLdouble", NameKind::Identity},
    {"static_cast", NameKind::Identity},
    {"glm::vec3", NameKind::Vector},
    {"glm::dvec3", NameKind::Vector},
    {"vec3", NameKind::Vector},
    {"THREE.Vector3", NameKind::Vector},
    {"Vector3", NameKind::Vector},
    {"XMFLOAT3", NameKind::Vector},
    {"XMVectorSet", NameKind::VectorWithW},
};

bool isNameStart(char c)
{
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

bool isNameChar(char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Reads expressions from a text with comments and strings blanked: numbers
// (1.5, 40.0f, 1e-3), + - * / and parentheses, the constants and functions
// above, [a, b, c] and vector constructors (flattened to their numbers).
class ExpressionReader
{
public:
    ExpressionReader(const std::string& text, std::size_t position) : text_(text), at_(position) {}

    std::size_t position() const { return at_; }

    // A qualified name (glm::vec3, THREE.Vector3, Math.PI) at the position, or "".
    std::string name()
    {
        skipSpace();
        std::string chain;
        std::size_t end = at_;
        while (end < text_.size() && isNameStart(text_[end])) {
            const std::size_t start = end;
            while (end < text_.size() && isNameChar(text_[end]))
                ++end;
            chain += text_.substr(start, end - start);
            if (text_.compare(end, 2, "::") == 0 && end + 2 < text_.size() && isNameStart(text_[end + 2]))
                chain += "::", end += 2;
            else if (end + 1 < text_.size() && text_[end] == '.' && isNameStart(text_[end + 1]))
                chain += ".", end += 1;
            else
                break;
        }
        at_ = end;
        return chain;
    }

    bool take(char c)
    {
        skipSpace();
        if (at_ < text_.size() && text_[at_] == c) {
            ++at_;
            return true;
        }
        return false;
    }

    // A template argument list <float>, skipped.
    void skipTemplateArguments()
    {
        if (take('<')) {
            const std::size_t close = text_.find('>', at_);
            at_ = close == std::string::npos ? text_.size() : close + 1;
        }
    }

    // The arguments after '(' up to the matching ')', each flattened to its numbers.
    std::vector<std::vector<Quantity>> arguments(char close = ')')
    {
        std::vector<std::vector<Quantity>> args;
        if (take(close))
            return args;
        do
            args.push_back(expression());
        while (take(','));
        if (!take(close))
            throw ReadFailure(std::string("expected '") + close + "'");
        return args;
    }

private:
    void skipSpace()
    {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])))
            ++at_;
    }

    static Quantity scalar(const std::vector<Quantity>& values)
    {
        if (values.size() != 1)
            throw ReadFailure("a vector where a number was expected");
        return values[0];
    }

    std::vector<Quantity> expression()
    {
        std::vector<Quantity> left = term();
        for (;;) {
            if (take('+'))
                left = {sum(scalar(left), scalar(term()), 1)};
            else if (take('-'))
                left = {sum(scalar(left), scalar(term()), -1)};
            else
                return left;
        }
    }

    std::vector<Quantity> term()
    {
        std::vector<Quantity> left = unary();
        for (;;) {
            if (take('*'))
                left = {scalar(left) * scalar(unary())};
            else if (take('/'))
                left = {scalar(left) / scalar(unary())};
            else
                return left;
        }
    }

    std::vector<Quantity> unary()
    {
        if (take('-'))
            return {Quantity{-1, 0} * scalar(unary())};
        if (take('+'))
            return unary();
        return primary();
    }

    std::vector<Quantity> primary()
    {
        skipSpace();
        if (take('(')) {
            std::vector<Quantity> inner = expression();
            if (!take(')'))
                throw ReadFailure("expected ')'");
            return inner;
        }
        if (take('['))
            return flatten(arguments(']'));
        if (at_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[at_])) || text_[at_] == '.'))
            return {number()};
        std::string called = name();
        if (called == "new")
            called = name();
        if (called.empty())
            throw ReadFailure(at_ < text_.size() ? "unexpected '" + std::string(1, text_[at_]) + "'"
                                                 : "unexpected end of the code");
        skipTemplateArguments();
        const bool call = take('(');
        if (const auto constant = kConstants.find(called); constant != kConstants.end()) {
            if (call && !take(')')) // glm::pi<float>()
                throw ReadFailure(called + " takes no arguments");
            return {constant->second};
        }
        const auto function = kFunctions.find(called);
        if (function == kFunctions.end() || !call)
            throw ReadFailure("unknown name '" + called + "' (write numbers)");
        std::vector<Quantity> values = flatten(arguments());
        switch (function->second) {
        case NameKind::Radians: return {scalar(values) * Quantity{1, 1}};
        case NameKind::Identity: return {scalar(values)};
        case NameKind::Vector: return values;
        case NameKind::VectorWithW:
            if (values.size() == 4)
                values.pop_back(); // XMVectorSet's w: not part of a point or direction
            return values;
        }
        return values;
    }

    Quantity number()
    {
        const char* begin = text_.c_str() + at_;
        char* end = nullptr;
        const double x = std::strtod(begin, &end);
        if (end == begin)
            throw ReadFailure("unreadable number");
        at_ += std::size_t(end - begin);
        if (at_ < text_.size() && (text_[at_] == 'f' || text_[at_] == 'F'))
            ++at_; // C++ float suffix
        return {x, 0};
    }

    static std::vector<Quantity> flatten(const std::vector<std::vector<Quantity>>& lists)
    {
        std::vector<Quantity> all;
        for (const auto& list : lists)
            all.insert(all.end(), list.begin(), list.end());
        return all;
    }

    const std::string& text_;
    std::size_t at_;
};

// Comments and string literals blanked (offsets kept), so that only code is read.
std::string codeOnly(std::string text)
{
    for (std::size_t i = 0; i < text.size(); ++i) {
        std::size_t end = i;
        if (text.compare(i, 2, "//") == 0)
            end = text.find('\n', i);
        else if (text.compare(i, 2, "/*") == 0)
            end = (end = text.find("*/", i + 2)) == std::string::npos ? end : end + 2;
        else if (text[i] == '\'' || text[i] == '"' || text[i] == '`')
            end = (end = text.find(text[i], i + 1)) == std::string::npos ? end : end + 1;
        else if (text[i] == '#') // preprocessor lines: #include <glm/glm.hpp>
            end = text.find('\n', i);
        else
            continue;
        end = std::min(end, text.size());
        std::fill(text.begin() + std::ptrdiff_t(i), text.begin() + std::ptrdiff_t(end), ' ');
        i = end;
    }
    return text;
}

enum class Sets { Perspective, Frustum, Ortho, LookAt, Eye, Up };

// A call that sets part of the camera, as recognized from its name.
struct CallForm {
    Sets sets = Sets::LookAt;
    bool radians = false;         // fovy in radians
    bool topBeforeBottom = false; // three.js's left, right, top, bottom
    bool reverseZ = false;        // wgpu-matrix's *ReverseZ: reversed depth, far = infinity by default
    std::optional<gl::Handedness> handedness;
};

CallForm form(Sets sets, bool topBeforeBottom = false)
{
    CallForm form;
    form.sets = sets;
    form.topBeforeBottom = topBeforeBottom;
    return form;
}

std::optional<gl::Handedness> handednessSuffix(const std::string& suffix)
{
    if (suffix.empty())
        return std::nullopt;
    return suffix == "LH" ? gl::Handedness::Left : gl::Handedness::Right;
}

// What a call named `chain` (gluPerspective, glm::perspectiveRH_ZO, camera.position.set, ...) sets.
std::optional<CallForm> recognize(const std::string& chain)
{
    static const std::map<std::string, CallForm> exact = {
        {"gluPerspective", form(Sets::Perspective)},
        {"glFrustum", form(Sets::Frustum)},
        {"glOrtho", form(Sets::Ortho)},
        {"gluOrtho2D", form(Sets::Ortho)},
        {"gluLookAt", form(Sets::LookAt)},
        {"PerspectiveCamera", form(Sets::Perspective)},
        {"OrthographicCamera", form(Sets::Ortho, true)},
        {"makePerspective", form(Sets::Frustum, true)},
        {"makeOrthographic", form(Sets::Ortho, true)},
        {"position.set", form(Sets::Eye)},
        {"up.set", form(Sets::Up)},
    };
    static const std::regex glmOrWgpu(
        "(perspective|infinitePerspective|frustum|ortho|lookAt)(ReverseZ)?(RH|LH)?(_NO|_ZO)?");
    static const std::regex directXMath(
        "XMMatrix(PerspectiveFov|PerspectiveOffCenter|OrthographicOffCenter|LookAt)(LH|RH)");
    const std::size_t cut = chain.find_last_of(".:");
    const std::string last = cut == std::string::npos ? chain : chain.substr(cut + 1);
    // three.js's setters are known by their object: camera.position.set, camera.up.set.
    const std::size_t objectCut = cut == std::string::npos ? cut : chain.find_last_of(".:", cut - 1);
    const std::string lastTwo = objectCut == std::string::npos ? chain : chain.substr(objectCut + 1);
    for (const std::string& key : {last, lastTwo})
        if (const auto it = exact.find(key); it != exact.end())
            return it->second;
    std::smatch m;
    std::string base;
    CallForm call;
    if (std::regex_match(last, m, glmOrWgpu)) {
        base = m[1];
        call.reverseZ = m[2].matched;
        call.handedness = handednessSuffix(m[3]);
    } else if (std::regex_match(last, m, directXMath)) {
        base = m[1];
        call.handedness = handednessSuffix(m[2]);
    } else {
        return std::nullopt;
    }
    const std::map<std::string, Sets> bases = {{"perspective", Sets::Perspective},
                                               {"infinitePerspective", Sets::Perspective},
                                               {"PerspectiveFov", Sets::Perspective},
                                               {"frustum", Sets::Frustum},
                                               {"PerspectiveOffCenter", Sets::Frustum},
                                               {"ortho", Sets::Ortho},
                                               {"OrthographicOffCenter", Sets::Ortho},
                                               {"lookAt", Sets::LookAt},
                                               {"LookAt", Sets::LookAt}};
    call.sets = bases.at(base);
    call.radians = call.sets == Sets::Perspective; // glm's, DirectXMath's and wgpu-matrix's fovy
    return call;
}

// What the pasted calls set.
struct Pasted {
    std::optional<gl::ProjectionSpec<double>> projection;
    std::string projectionCall;
    std::vector<Arg> projectionArgs; // as written, for naming an argument in an error
    bool reversed = false;
    std::optional<gl::Handedness> handedness, lookAtHandedness;
    std::optional<Vec3<double>> eye, center, up;
    std::string lookAtCall;
};

std::string argumentCountError(const std::string& call, const std::string& takes, std::size_t got)
{
    return call + " takes " + takes + " numbers; got " + std::to_string(got);
}

// The projection of `kind` from a call's numbers in its order (defaults for the numbers it may leave out).
void readProjection(Pasted& pasted, const std::string& call, const CallForm& form, std::vector<Quantity> numbers)
{
    if (pasted.projection)
        throw InputError("code",
                         "two projection calls (" + pasted.projectionCall + " and " + call + "): paste one camera");
    const bool perspective = form.sets == Sets::Perspective;
    const std::size_t full = perspective ? 4 : 6;
    if (form.reverseZ && numbers.size() == full - 1)
        numbers.push_back({INFINITY, 0}); // wgpu-matrix's default far
    else if (call.find("infinitePerspective") != std::string::npos && numbers.size() == 3)
        numbers.push_back({INFINITY, 0});
    else if (form.sets == Sets::Ortho && numbers.size() == 4)
        numbers.insert(numbers.end(), {{-1, 0}, {1, 0}}); // glm::ortho and gluOrtho2D without depth: near -1, far 1
    if (numbers.size() != full)
        throw InputError("code", argumentCountError(call,
                                                    perspective ? "4 (fovy, aspect, near, far)"
                                                                : "6 (left, right, bottom, top, near, far)",
                                                    numbers.size()));
    gl::ProjectionSpec<double> spec = perspective ? gl::ProjectionSpec<double>(gl::Perspective<double>{})
                                      : form.sets == Sets::Frustum ? gl::ProjectionSpec<double>(gl::Frustum<double>{})
                                                                   : gl::ProjectionSpec<double>(gl::Ortho<double>{});
    // Near and far exchanged in a perspective or ortho call is the reversed-depth idiom: its matrix is the
    // reversed camera's. A frustum's is not (its x and y scale with near), so it is read as written.
    const double zNear = numbers[full - 2].value(), zFar = numbers[full - 1].value();
    // A perspective's far at or behind the eye is no exchange but a bad far, refused as such below.
    const bool swapped = form.sets != Sets::Frustum && zNear > zFar && (!perspective || zFar > 0);
    pasted.projectionArgs = projectionArgs(spec, form.topBeforeBottom, swapped);
    for (std::size_t i = 0; i < full; ++i) {
        const Arg& arg = pasted.projectionArgs[i];
        const bool fovy = arg.field == gl::kProjectionField + "fovy_deg";
        *projectionNumber(spec, arg.field.substr(gl::kProjectionField.size())) =
            fovy ? (form.radians ? numbers[i].degrees() : numbers[i].value()) : numbers[i].value();
        pasted.projectionArgs[i].value = numbers[i].value();
    }
    pasted.projection = spec;
    pasted.projectionCall = call;
    pasted.reversed = form.reverseZ || swapped;
}

void readLookAt(Pasted& pasted, const std::string& call, Sets sets, const std::vector<Quantity>& numbers)
{
    const auto vec = [&](std::size_t first) {
        return Vec3<double>(numbers[first].value(), numbers[first + 1].value(), numbers[first + 2].value());
    };
    if (sets == Sets::LookAt && numbers.size() == 9) {
        if (pasted.eye && pasted.center)
            throw InputError("code",
                             "two look-at calls (" + pasted.lookAtCall + " and " + call + "): paste one camera");
        pasted.eye = vec(0), pasted.center = vec(3), pasted.up = vec(6);
    } else if (numbers.size() == 3) {
        (sets == Sets::Eye ? pasted.eye : sets == Sets::Up ? pasted.up : pasted.center) = vec(0);
    } else {
        throw InputError(
            "code",
            argumentCountError(call, sets == Sets::LookAt ? "9 (eye, center, up) or 3 (center)" : "3", numbers.size()));
    }
    pasted.lookAtCall = pasted.lookAtCall.empty() ? call : pasted.lookAtCall;
}

void readCall(Pasted& pasted, const std::string& call, const CallForm& form, ExpressionReader& reader)
{
    std::vector<Quantity> numbers;
    const auto args = [&] {
        try {
            return reader.arguments();
        } catch (const ReadFailure& failure) {
            throw InputError("code", call + ": " + failure.what());
        }
    }();
    for (const auto& arg : args)
        numbers.insert(numbers.end(), arg.begin(), arg.end());
    if (numbers.empty() && (call.find("Camera") != std::string::npos))
        return; // new THREE.PerspectiveCamera(): the matrix is set after
    // A camera has one handedness: a look-at call's suffix decides it, a projection call's only without one
    // (glm's left-handed frustum is written as frustumRH with z mirrored, see planFor).
    if (form.handedness && (form.sets == Sets::LookAt || !pasted.lookAtHandedness))
        (form.sets == Sets::LookAt ? pasted.lookAtHandedness : pasted.handedness) = form.handedness;
    if (form.sets == Sets::Perspective || form.sets == Sets::Frustum || form.sets == Sets::Ortho)
        readProjection(pasted, call, form, numbers);
    else
        readLookAt(pasted, call, form.sets, numbers);
}

Pasted readPasted(const std::string& code)
{
    const std::string text = codeOnly(code);
    Pasted pasted;
    bool any = false;
    for (std::size_t i = 0; i < text.size();) {
        const bool startsName = isNameStart(text[i]) && (i == 0 || !(isNameChar(text[i - 1]) || text[i - 1] == '.'));
        if (!startsName) {
            ++i;
            continue;
        }
        ExpressionReader reader(text, i);
        const std::string chain = reader.name();
        reader.skipTemplateArguments();
        const std::optional<CallForm> form = recognize(chain);
        if (form && reader.take('(')) {
            readCall(pasted, chain, *form, reader);
            any = true;
        }
        i = form ? std::max(reader.position(), i + chain.size()) : i + chain.size();
    }
    if (!any)
        throw InputError("code",
                         "no camera call recognized: expected gluPerspective(...), glFrustum(...), "
                         "glOrtho(...), gluLookAt(...), glm::perspective(...), glm::lookAt(...), "
                         "XMMatrixPerspectiveFovLH(...), XMMatrixLookAtLH(...), new THREE.PerspectiveCamera(...), "
                         "camera.lookAt(...), mat4.perspective(...) or mat4.lookAt(...)");
    return pasted;
}

} // namespace

std::string dialectName(Dialect dialect)
{
    return namesOf(dialect).name;
}

std::string dialectTitle(Dialect dialect)
{
    return namesOf(dialect).title;
}

Dialect dialectNamed(const std::string& name, const std::string& field)
{
    std::string known;
    for (const DialectNames& names : kDialectNames) {
        if (name == names.name)
            return names.dialect;
        known += (known.empty() ? "" : ", ") + std::string(names.name);
    }
    throw InputError(field, "must be one of " + known + " (got \"" + name + "\")");
}

CameraCode cameraCode(const gl::Camera<double>& camera, Dialect dialect)
{
    validateCamera(camera);
    const Plan plan = planFor(camera, dialect);
    CodeWriter out(spellingOf(dialect));
    out << conventionsComment(camera);
    using Writer = void (*)(CodeWriter&, const Camera&, const Plan&);
    const std::map<Dialect, Writer> writers = {{Dialect::OpenGL, writeOpenGL},
                                               {Dialect::Glm, writeGlm},
                                               {Dialect::DirectXMath, writeDirectXMath},
                                               {Dialect::ThreeJs, writeThreeJs},
                                               {Dialect::WgpuMatrix, writeWgpuMatrix}};
    writers.at(dialect)(out, camera, plan);
    return out.take();
}

double stepFor(double value)
{
    return std::pow(10.0, std::floor(std::log10(std::max(std::abs(value), 1.0) * 0.005)));
}

double steppedValue(double from, int steps)
{
    if (!std::isfinite(from))
        return from;
    const double unit = stepFor(from);
    // Divided rather than multiplied when below 1: 40.3, not 40.300000000000004.
    const double scale = unit < 1 ? std::round(1 / unit) : unit;
    const double count = std::round(from / unit) + steps;
    return unit < 1 ? count / scale : count * scale;
}

gl::Camera<double> withField(const gl::Camera<double>& camera, const std::string& field, double value)
{
    static const std::regex lookAtPattern(R"(camera\.look_at\.(eye|center|up)\[([012])\])");
    Camera out = camera;
    std::smatch m;
    if (std::regex_match(field, m, lookAtPattern)) {
        Vec3<double>& v = m[1] == "eye" ? out.lookAt.eye : m[1] == "center" ? out.lookAt.center : out.lookAt.up;
        v[std::stoi(m[2])] = value;
    } else if (field.compare(0, gl::kProjectionField.size(), gl::kProjectionField) == 0) {
        double* number = projectionNumber(out.projection, field.substr(gl::kProjectionField.size()));
        if (!number)
            throw InputError(field,
                             "the camera's projection is " + kindName(out.projection) + ", which has no such number");
        *number = value;
    } else {
        throw InputError(field, "is not a camera number (expected camera.look_at.eye[0..2], center[0..2], up[0..2] "
                                "or camera.projection.fovy_deg, aspect, left, right, bottom, top, near, far)");
    }
    try {
        validateCamera(out);
    } catch (const InputError& e) {
        if (e.field() == field)
            throw;
        throw InputError(field, formatShortest(value) + " makes no valid camera: " + e.what());
    }
    return out;
}

gl::Camera<double> applyCode(const gl::Camera<double>& camera, const std::string& code)
{
    const Pasted pasted = readPasted(code);
    Camera out = camera;
    if (pasted.projection) {
        out.projection = *pasted.projection;
        if (pasted.reversed)
            out.depth = gl::DepthMode::Reversed;
        try {
            std::visit([](const auto& p) { gl::validate(p); }, out.projection);
        } catch (const InputError& e) {
            for (std::size_t i = 0; i < pasted.projectionArgs.size(); ++i)
                if (pasted.projectionArgs[i].field == e.field())
                    throw InputError("code", pasted.projectionCall + " argument " + std::to_string(i + 1) + " (" +
                                                 e.field().substr(gl::kProjectionField.size()) + "): " + e.reason());
            throw InputError("code", pasted.projectionCall + ": " + e.what());
        }
    }
    out.handedness = pasted.lookAtHandedness.value_or(pasted.handedness.value_or(out.handedness));
    out.lookAt.eye = pasted.eye.value_or(out.lookAt.eye);
    out.lookAt.center = pasted.center.value_or(out.lookAt.center);
    out.lookAt.up = pasted.up.value_or(out.lookAt.up);
    try {
        gl::eyeBasis(out.lookAt);
    } catch (const InputError& e) {
        throw InputError("code", (pasted.lookAtCall.empty() ? "the camera" : pasted.lookAtCall) + ": " + e.what());
    }
    return out;
}

} // namespace viewpipe::report
