// The camera as code (viewpipe/report/code.hpp): every number located and
// editable, pasted code read back, and the glm and legacy OpenGL dialects
// compiled and run, their matrices compared with gl::viewMatrix and
// gl::projectionMatrix.
//
// The libraries' formulas the generated code relies on, as read in their sources:
// - glm 0.9.9.8 (/usr/include/glm/ext/matrix_clip_space.inl): perspectiveRH_NO has
//   [2][2] = -(f + n)/(f - n), [3][2] = -2fn/(f - n), so exchanging n and f gives
//   (f + n)/(f - n), 2fn/(f - n): OpenGL's reversed z' = -z; perspectiveRH_ZO's
//   f/(n - f), -fn/(f - n) become n/(f - n), fn/(f - n): (w - z)/2. frustum*'s
//   [0][0] = 2n/(r - l) changes with n, so a reversed frustum needs the extra matrix.
//   infinitePerspectiveRH/LH exist only with depth [-1, 1] ([2][2] = -+1, [3][2] = -2n).
// - DirectXMath (Inc/DirectXMathMatrix.inl): XMMatrixPerspectiveFovLH's fRange =
//   FarZ/(FarZ - NearZ), M[3][2] = -fRange * NearZ: exchanged, NearZ/(NearZ - FarZ) and
//   FarZ NearZ/(FarZ - NearZ), the reversed [0, 1] depth; XMMatrixLookAtRH's rows are
//   normalize(eye - focus) = -f, up x -f = s, -f x s = u.
// - three.js (src/math/Matrix4.js makePerspective, WebGL system): c = -(far + near)/(far - near),
//   d = -2 far near/(far - near): NaN for far = Infinity, so the limit is written out.
// - wgpu-matrix 3.4 (src/mat4-impl.ts): perspective and perspectiveReverseZ take zFar =
//   Infinity ([10] = -1, [14] = -zNear; reversed 0, zNear); frustum's [10] = far/(near - far)
//   does not; frustumReverseZ does.

#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "viewpipe/format.hpp"
#include "viewpipe/report/code.hpp"

namespace viewpipe::report
{
namespace
{

using Camera = gl::Camera<double>;

enum class Kind { Perspective, Frustum, Ortho, InfinitePerspective, InfiniteFrustum };
constexpr Kind kKinds[] = {Kind::Perspective, Kind::Frustum, Kind::Ortho, Kind::InfinitePerspective,
                           Kind::InfiniteFrustum};

Camera cameraOf(Kind kind, gl::Api api, gl::Handedness handedness, gl::DepthMode depth)
{
    Camera camera;
    camera.lookAt = {{3, 2, 5}, {0, 0.5, 0}, {0, 1, 0}};
    const double inf = std::numeric_limits<double>::infinity();
    switch (kind) {
    case Kind::Perspective: camera.projection = gl::Perspective<double>{40, 1.5, 0.1, 100}; break;
    case Kind::Frustum: camera.projection = gl::Frustum<double>{-0.2, 0.1, -0.08, 0.12, 0.1, 50}; break;
    case Kind::Ortho: camera.projection = gl::Ortho<double>{-3, 2, -1.5, 2.5, 0.5, 20}; break;
    case Kind::InfinitePerspective: camera.projection = gl::Perspective<double>{40, 1.5, 0.1, inf}; break;
    case Kind::InfiniteFrustum: camera.projection = gl::Frustum<double>{-0.2, 0.1, -0.08, 0.12, 0.1, inf}; break;
    }
    camera.api = api;
    camera.handedness = handedness;
    camera.depth = depth;
    return camera;
}

// Every camera the dialects must write: each kind, API, handedness and depth mode.
std::vector<Camera> allCameras()
{
    std::vector<Camera> cameras;
    for (const Kind kind : kKinds)
        for (const gl::Api api : gl::kApis)
            for (const gl::Handedness handedness : {gl::Handedness::Right, gl::Handedness::Left})
                for (const gl::DepthMode depth : {gl::DepthMode::Standard, gl::DepthMode::Reversed})
                    cameras.push_back(cameraOf(kind, api, handedness, depth));
    return cameras;
}

std::string describe(const Camera& camera)
{
    return gl::apiName(camera.api) + ", " + gl::handednessName(camera.handedness) + "-handed, " +
           gl::depthModeName(camera.depth) + ", projection " + std::to_string(camera.projection.index()) + ", far " +
           formatShortest(std::visit([](const auto& p) { return p.zFar; }, camera.projection));
}

// |a - b| within `relative` of the matrix's largest entry, entry by entry.
void expectMatrixNear(const Mat4<double>& actual, const Mat4<double>& expected, double relative)
{
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(actual(r, c), expected(r, c), relative * scale) << "entry (" << r << ", " << c << ")\n"
                                                                        << "actual\n"
                                                                        << actual << "\nexpected\n"
                                                                        << expected;
}

TEST(CodeDialects, NamesRoundTripAndUnknownNamesAreRefused)
{
    for (const Dialect dialect : kDialects)
        EXPECT_EQ(dialectNamed(dialectName(dialect), "--dialect"), dialect);
    EXPECT_EQ(dialectTitle(Dialect::ThreeJs), "three.js");
    try {
        dialectNamed("vulkan", "--dialect");
        FAIL() << "accepted an unknown dialect";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "--dialect");
        EXPECT_NE(e.reason().find("wgpu-matrix"), std::string::npos) << e.reason();
    }
}

TEST(CodeNumbers, EveryNumberReadsBackAsItsFieldsValue)
{
    for (const Dialect dialect : kDialects)
        for (const Camera& camera : allCameras()) {
            SCOPED_TRACE(dialectName(dialect) + ": " + describe(camera));
            const CameraCode code = cameraCode(camera, dialect);
            ASSERT_FALSE(code.text.empty());
            std::map<std::string, int> seen;
            std::size_t previousEnd = 0;
            for (const CodeNumber& number : code.numbers) {
                ASSERT_LE(number.offset + number.length, code.text.size());
                EXPECT_GE(number.offset, previousEnd) << "numbers out of order or overlapping";
                previousEnd = number.offset + number.length;
                const std::string digits = code.text.substr(number.offset, number.length);
                char* end = nullptr;
                EXPECT_EQ(std::strtod(digits.c_str(), &end), number.value) << digits;
                EXPECT_EQ(*end, '\0') << "\"" << digits << "\" is more than a number";
                EXPECT_FALSE(number.tooltip.empty()) << number.field;
                // A valid path: setting the field to its own value changes nothing.
                const Camera same = withField(camera, number.field, number.value);
                EXPECT_EQ(gl::projectionMatrix(same), gl::projectionMatrix(camera)) << number.field;
                EXPECT_EQ(gl::viewMatrix(same), gl::viewMatrix(camera)) << number.field;
                ++seen[number.field];
            }
            // Each look-at coordinate and each projection number once (an infinite far may be left unwritten).
            const bool perspective = std::holds_alternative<gl::Perspective<double>>(camera.projection);
            const bool infinite = std::isinf(std::visit([](const auto& p) { return p.zFar; }, camera.projection));
            EXPECT_EQ(seen.size(), 9u + (perspective ? 4 : 6) - (infinite && !seen.count("camera.projection.far")));
            for (const auto& [field, count] : seen)
                EXPECT_EQ(count, 1) << field;
        }
}

TEST(CodeNumbers, KnownTextForALegacyOpenGLCamera)
{
    const CameraCode code = cameraCode(
        cameraOf(Kind::Perspective, gl::Api::OpenGL, gl::Handedness::Right, gl::DepthMode::Standard), Dialect::OpenGL);
    EXPECT_NE(code.text.find("gluPerspective(40, 1.5, 0.1, 100);"), std::string::npos) << code.text;
    EXPECT_NE(code.text.find("gluLookAt(3, 2, 5, 0, 0.5, 0, 0, 1, 0);"), std::string::npos) << code.text;
    EXPECT_EQ(code.text.find("glScaled"), std::string::npos) << code.text;
    ASSERT_EQ(code.numbers.size(), 13u);
    EXPECT_EQ(code.numbers[0].field, "camera.projection.fovy_deg");
    EXPECT_EQ(code.numbers[0].tooltip, "fovy: the vertical field of view, in degrees");
    EXPECT_EQ(code.numbers[4].field, "camera.look_at.eye[0]");
}

TEST(CodeNumbers, DegreesStayDegreesInsideRadiansConversions)
{
    const Camera camera = cameraOf(Kind::Perspective, gl::Api::Vulkan, gl::Handedness::Right, gl::DepthMode::Standard);
    EXPECT_NE(cameraCode(camera, Dialect::Glm).text.find("glm::radians(40.0f)"), std::string::npos);
    EXPECT_NE(cameraCode(camera, Dialect::DirectXMath).text.find("XMConvertToRadians(40.0f)"), std::string::npos);
    EXPECT_NE(cameraCode(camera, Dialect::WgpuMatrix).text.find("40 * Math.PI / 180"), std::string::npos);
    EXPECT_NE(cameraCode(camera, Dialect::ThreeJs).text.find("PerspectiveCamera(40, 1.5, 0.1, 100)"),
              std::string::npos);
}

// Pasting a camera's code into another camera with the same API and depth
// mode gives the first camera's matrices, wherever the code is calls (an
// infinite far written out as a matrix sets only the look-at).
TEST(CodeRoundTrip, PastedCodeReproducesTheCamerasMatrices)
{
    for (const Dialect dialect : kDialects)
        for (const Camera& camera : allCameras()) {
            const std::string text = cameraCode(camera, dialect).text;
            SCOPED_TRACE(dialectName(dialect) + ": " + describe(camera) + "\n" + text);
            Camera other = camera;
            other.lookAt = {{-1, 4, 2}, {1, 1, 1}, {0, 0, 1}};
            other.projection = std::holds_alternative<gl::Ortho<double>>(camera.projection)
                                   ? gl::ProjectionSpec<double>(gl::Perspective<double>{60, 1, 1, 10})
                                   : gl::ProjectionSpec<double>(gl::Ortho<double>{-1, 1, -1, 1, 1, 10});
            // glm's and DirectXMath's *LH/*RH calls name the handedness; the others keep the camera's.
            const bool handedCalls = dialect == Dialect::Glm || dialect == Dialect::DirectXMath;
            if (handedCalls)
                other.handedness =
                    camera.handedness == gl::Handedness::Left ? gl::Handedness::Right : gl::Handedness::Left;
            const bool infinite = std::isinf(std::visit([](const auto& p) { return p.zFar; }, camera.projection));
            const bool perspective = std::holds_alternative<gl::Perspective<double>>(camera.projection);
            const bool pasteable =
                !infinite || (perspective && dialect == Dialect::Glm) ||
                (dialect == Dialect::WgpuMatrix && (perspective || camera.depth == gl::DepthMode::Reversed));
            const Camera pasted = applyCode(other, text);
            expectMatrixNear(gl::viewMatrix(pasted), gl::viewMatrix(camera), 1e-14);
            if (pasteable)
                expectMatrixNear(gl::projectionMatrix(pasted), gl::projectionMatrix(camera), 1e-14);
            else // the projection as it was (its handedness may follow the look-at call's)
                EXPECT_EQ(gl::projectionMatrix(pasted.projection), gl::projectionMatrix(other.projection));
        }
}

// ---------------------------------------------------------------------------
// The generated code compiled and run

std::filesystem::path scratchDirectory(const std::string& name)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("viewpipe-code-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

bool haveCompiler()
{
    return std::system("g++ --version > /dev/null 2>&1") == 0;
}

// The code's #include lines, and the rest as a function body.
std::pair<std::string, std::string> splitIncludes(const std::string& text)
{
    std::istringstream in(text);
    std::string line, includes, body;
    while (std::getline(in, line))
        (line.rfind("#include", 0) == 0 ? includes : body) += line + "\n";
    return {includes, body};
}

// Compiles `program` with g++ and returns what it prints, one matrix a line
// (16 numbers column by column); fails the test on errors.
std::vector<Mat4<double>> compileAndRun(const std::string& name, const std::string& program)
{
    const std::filesystem::path dir = scratchDirectory(name);
    const std::filesystem::path source = dir / "camera.cpp", binary = dir / "camera", output = dir / "out.txt",
                                log = dir / "log.txt";
    std::ofstream(source) << program;
    const std::string compile =
        "g++ -std=c++17 -w -o '" + binary.string() + "' '" + source.string() + "' > '" + log.string() + "' 2>&1";
    std::vector<Mat4<double>> matrices;
    if (std::system(compile.c_str()) != 0) {
        std::ifstream in(log);
        ADD_FAILURE() << "g++ failed on " << source << ":\n" << std::string(std::istreambuf_iterator<char>(in), {});
        return matrices;
    }
    EXPECT_EQ(std::system(("'" + binary.string() + "' > '" + output.string() + "'").c_str()), 0);
    std::ifstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream numbers(line);
        Mat4<double> m;
        for (int i = 0; i < 16; ++i)
            numbers >> m(i % 4, i / 4);
        matrices.push_back(m);
    }
    std::filesystem::remove_all(dir);
    return matrices;
}

// Every camera's glm code, compiled against the system's glm and run: its
// matrices are ViewPipe's to float rounding.
TEST(CodeCompiled, GlmCodeGivesTheCamerasMatrices)
{
    if (!haveCompiler() || !std::filesystem::exists("/usr/include/glm/glm.hpp"))
        GTEST_SKIP() << "needs g++ and glm (/usr/include/glm)";
    const std::vector<Camera> cameras = allCameras();
    std::string includes, cases, calls;
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        const auto [caseIncludes, body] = splitIncludes(cameraCode(cameras[i], Dialect::Glm).text);
        includes = caseIncludes;
        cases += "void case" + std::to_string(i) + "()\n{\n" + body + "print(view);\nprint(proj);\n}\n";
        calls += "case" + std::to_string(i) + "();\n";
    }
    const std::string program = "#include <cmath>\n#include <cstdio>\n" + includes +
                                "void print(const glm::mat4& m)\n{\n"
                                "for (int c = 0; c < 4; ++c) for (int r = 0; r < 4; ++r) std::printf(\"%.9g \", "
                                "double(m[c][r]));\nstd::printf(\"\\n\");\n}\n" +
                                cases + "int main()\n{\n" + calls + "}\n";
    const std::vector<Mat4<double>> printed = compileAndRun("glm", program);
    ASSERT_EQ(printed.size(), 2 * cameras.size());
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        SCOPED_TRACE(describe(cameras[i]) + "\n" + cameraCode(cameras[i], Dialect::Glm).text);
        expectMatrixNear(printed[2 * i], gl::viewMatrix(cameras[i]), 1e-5);
        expectMatrixNear(printed[2 * i + 1], gl::projectionMatrix(cameras[i]), 1e-5);
    }
}

// The fixed-function calls the legacy OpenGL code uses, as their reference
// pages define them (column-major; each call multiplies the current matrix
// on the right): an independent stand-in for a GL context.
const char* const kLegacyOpenGL = R"(#include <cmath>
#include <cstdio>
typedef double GLdouble;
enum { GL_PROJECTION, GL_MODELVIEW };
static double stack[2][16];
static int current = GL_MODELVIEW;
void glMatrixMode(int mode) { current = mode; }
void glMultMatrixd(const double* m)
{
    double product[16];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            product[4 * c + r] = 0;
            for (int k = 0; k < 4; ++k)
                product[4 * c + r] += stack[current][4 * k + r] * m[4 * c + k];
        }
    for (int i = 0; i < 16; ++i)
        stack[current][i] = product[i];
}
void glLoadIdentity()
{
    for (int i = 0; i < 16; ++i)
        stack[current][i] = i % 5 == 0;
}
void glScaled(double x, double y, double z)
{
    const double m[16] = {x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 1};
    glMultMatrixd(m);
}
void glFrustum(double l, double r, double b, double t, double n, double f)
{
    const double m[16] = {2 * n / (r - l), 0, 0, 0, 0, 2 * n / (t - b), 0, 0,
                          (r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1, 0, 0, -2 * f * n / (f - n), 0};
    glMultMatrixd(m);
}
void glOrtho(double l, double r, double b, double t, double n, double f)
{
    const double m[16] = {2 / (r - l), 0, 0, 0, 0, 2 / (t - b), 0, 0, 0, 0, -2 / (f - n), 0,
                          -(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1};
    glMultMatrixd(m);
}
void gluPerspective(double fovy, double aspect, double n, double f)
{
    const double c = 1 / std::tan(fovy * M_PI / 360);
    const double m[16] = {c / aspect, 0, 0, 0, 0, c, 0, 0, 0, 0, (f + n) / (n - f), -1, 0, 0, 2 * f * n / (n - f), 0};
    glMultMatrixd(m);
}
void gluLookAt(double ex, double ey, double ez, double cx, double cy, double cz, double ux, double uy, double uz)
{
    double f[3] = {cx - ex, cy - ey, cz - ez};
    const double fn = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f)
        x /= fn;
    double s[3] = {f[1] * uz - f[2] * uy, f[2] * ux - f[0] * uz, f[0] * uy - f[1] * ux};
    const double sn = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (double& x : s)
        x /= sn;
    const double u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
    const double m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, 0, 0, 0, 1};
    glMultMatrixd(m);
    const double t[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -ex, -ey, -ez, 1};
    glMultMatrixd(t);
}
void print(int mode)
{
    for (int i = 0; i < 16; ++i)
        std::printf("%.17g ", stack[mode][i]);
    std::printf("\n");
}
)";

TEST(CodeCompiled, LegacyOpenGLCodeGivesTheCamerasMatrices)
{
    if (!haveCompiler())
        GTEST_SKIP() << "needs g++";
    const std::vector<Camera> cameras = allCameras();
    std::string cases, calls;
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        cases += "void case" + std::to_string(i) + "()\n{\n" + cameraCode(cameras[i], Dialect::OpenGL).text +
                 "print(GL_MODELVIEW);\nprint(GL_PROJECTION);\n}\n";
        calls += "case" + std::to_string(i) + "();\n";
    }
    const std::vector<Mat4<double>> printed =
        compileAndRun("opengl", kLegacyOpenGL + cases + "int main()\n{\n" + calls + "}\n");
    ASSERT_EQ(printed.size(), 2 * cameras.size());
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        SCOPED_TRACE(describe(cameras[i]) + "\n" + cameraCode(cameras[i], Dialect::OpenGL).text);
        expectMatrixNear(printed[2 * i], gl::viewMatrix(cameras[i]), 1e-13);
        expectMatrixNear(printed[2 * i + 1], gl::projectionMatrix(cameras[i]), 1e-13);
    }
}

// ---------------------------------------------------------------------------
// Refusals

void expectRefused(const std::function<void()>& call, const std::string& field, const std::string& mention)
{
    try {
        call();
        ADD_FAILURE() << "accepted; expected an error naming " << field;
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), field) << e.what();
        EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
    }
}

TEST(CodeRefusals, WithFieldNamesTheFieldOfABadValue)
{
    const Camera perspective =
        cameraOf(Kind::Perspective, gl::Api::OpenGL, gl::Handedness::Right, gl::DepthMode::Standard);
    const Camera ortho = cameraOf(Kind::Ortho, gl::Api::OpenGL, gl::Handedness::Right, gl::DepthMode::Standard);
    const std::string fovy = "camera.projection.fovy_deg";
    expectRefused([&] { withField(perspective, fovy, 0); }, fovy, "between 0 and 180");
    expectRefused([&] { withField(perspective, "camera.projection.aspect", -1); }, "camera.projection.aspect",
                  "greater than 0");
    expectRefused([&] { withField(perspective, "camera.projection.near", 0); }, "camera.projection.near",
                  "greater than 0");
    // The core names far when near meets it; the error still names the field set.
    expectRefused([&] { withField(ortho, "camera.projection.near", 20); }, "camera.projection.near",
                  "empty volume");
    expectRefused([&] { withField(perspective, "camera.projection.left", 1); }, "camera.projection.left",
                  "perspective");
    expectRefused([&] { withField(perspective, "camera.look_at.up[1]", 0); }, "camera.look_at.up[1]", "");
    expectRefused([&] { withField(perspective, "camera.look_at.eye[3]", 1); }, "camera.look_at.eye[3]",
                  "not a camera number");
    expectRefused([&] { withField(perspective, fovy, std::nan("")); }, fovy, "");
    const Camera moved = withField(perspective, fovy, 60);
    EXPECT_EQ(std::get<gl::Perspective<double>>(moved.projection).fovyDegrees, 60);
    EXPECT_EQ(withField(perspective, "camera.look_at.up[2]", 0.25).lookAt.up.z(), 0.25);
}

TEST(CodeRefusals, ApplyCodeNamesTheCallAndItsArgument)
{
    const Camera camera = cameraOf(Kind::Perspective, gl::Api::OpenGL, gl::Handedness::Right, gl::DepthMode::Standard);
    const auto paste = [&](const std::string& text) { return [&camera, text] { applyCode(camera, text); }; };
    expectRefused(paste("int main() { return 0; }"), "code", "no camera call recognized");
    expectRefused(paste("// gluPerspective(45, 1.5, 0.1, 100);"), "code", "no camera call recognized");
    expectRefused(paste("gluPerspective(0, 1.5, 0.1, 100);"), "code", "gluPerspective argument 1 (fovy_deg)");
    expectRefused(paste("glm::perspective(glm::radians(45.0f), 0.0f, 0.1f, 100.0f)"), "code",
                  "glm::perspective argument 2 (aspect)");
    expectRefused(paste("glOrtho(-1, 1, 2, 2, 0.1, 100);"), "code", "glOrtho argument 4 (top)");
    // A far behind the eye is a bad far, not near and far exchanged (reversed depth).
    expectRefused(paste("glm::perspective(glm::radians(45.0f), 1.5f, 1.0f, -5.0f)"), "code",
                  "glm::perspective argument 4 (far)");
    expectRefused(paste("gluPerspective(45, 1.5, 0.1);"), "code", "takes 4");
    expectRefused(paste("gluPerspective(fovy, 1.5, 0.1, 100);"), "code", "unknown name 'fovy'");
    expectRefused(paste("gluPerspective(45, 1.5, 0.1, 100"), "code", "expected ')'");
    expectRefused(paste("gluLookAt(1, 1, 1, 1, 1, 1, 0, 1, 0);"), "code", "gluLookAt: camera.look_at.center");
    expectRefused(paste("gluPerspective(45, 1, 1, 9); glOrtho(-1, 1, -1, 1, 1, 9);"), "code", "two projection calls");
    expectRefused(paste("glm::lookAtLH(glm::vec3(1, 2, 3), glm::vec3(0), glm::vec3(0, 1, 0));"), "code", "takes 9");
}

// ---------------------------------------------------------------------------
// Known values

TEST(CodeApply, KnownCallsSetKnownValues)
{
    const Camera camera = cameraOf(Kind::Ortho, gl::Api::Vulkan, gl::Handedness::Right, gl::DepthMode::Standard);

    const Camera glu = applyCode(camera, "gluPerspective(45, 1.333, 0.1, 100);");
    const auto& p = std::get<gl::Perspective<double>>(glu.projection);
    EXPECT_EQ(p.fovyDegrees, 45);
    EXPECT_EQ(p.aspect, 1.333);
    EXPECT_EQ(p.zNear, 0.1);
    EXPECT_EQ(p.zFar, 100);
    EXPECT_EQ(glu.api, gl::Api::Vulkan);
    EXPECT_EQ(glu.lookAt.eye, camera.lookAt.eye);

    // XM_PIDIV4 is 45 degrees exactly; the LH suffix sets the handedness, the API stays.
    const Camera dx =
        applyCode(camera, "XMMATRIX proj = XMMatrixPerspectiveFovLH(XM_PIDIV4, 16.f/9.f, 0.1f, 100.f);");
    const auto& q = std::get<gl::Perspective<double>>(dx.projection);
    EXPECT_EQ(q.fovyDegrees, 45);
    EXPECT_DOUBLE_EQ(q.aspect, 16.0 / 9.0);
    EXPECT_EQ(dx.handedness, gl::Handedness::Left);
    EXPECT_EQ(dx.api, gl::Api::Vulkan);

    EXPECT_EQ(std::get<gl::Perspective<double>>(
                  applyCode(camera, "glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 10.0f)").projection)
                  .fovyDegrees,
              60);
    EXPECT_EQ(std::get<gl::Perspective<double>>(
                  applyCode(camera, "glm::perspective(glm::pi<float>() / 3.0f, 1.5f, 0.1f, 10.0f)").projection)
                  .fovyDegrees,
              60);
    EXPECT_NEAR(std::get<gl::Perspective<double>>(
                    applyCode(camera, "mat4.perspective(0.785398, 1.5, 0.1, 10)").projection)
                    .fovyDegrees,
                45, 1e-4);

    // Near and far exchanged: the reversed-depth idiom.
    const Camera swapped = applyCode(camera, "gluPerspective(45, 1.5, 100, 0.1);");
    EXPECT_EQ(swapped.depth, gl::DepthMode::Reversed);
    EXPECT_EQ(std::get<gl::Perspective<double>>(swapped.projection).zNear, 0.1);
    EXPECT_EQ(std::get<gl::Perspective<double>>(swapped.projection).zFar, 100);

    // wgpu-matrix's reversed perspective: far defaults to infinity.
    const Camera wgpu = applyCode(camera, "const proj = mat4.perspectiveReverseZ(Math.PI / 4, 1.5, 0.1);");
    EXPECT_EQ(wgpu.depth, gl::DepthMode::Reversed);
    EXPECT_EQ(std::get<gl::Perspective<double>>(wgpu.projection).fovyDegrees, 45);
    EXPECT_TRUE(std::isinf(std::get<gl::Perspective<double>>(wgpu.projection).zFar));

    // three.js: left, right, top, bottom; the camera's pose in three calls.
    const Camera three = applyCode(camera, "const camera = new THREE.OrthographicCamera(-2, 2, 1, -1, 0.5, 10);\n"
                                                 "camera.position.set(1, 2, 3);\ncamera.up.set(0, 0, 1);\n"
                                                 "camera.lookAt(new THREE.Vector3(0, 0, 0));");
    const auto& box = std::get<gl::Ortho<double>>(three.projection);
    EXPECT_EQ(box.bottom, -1);
    EXPECT_EQ(box.top, 1);
    EXPECT_EQ(three.lookAt.eye, Vec3<double>(1, 2, 3));
    EXPECT_EQ(three.lookAt.up, Vec3<double>(0, 0, 1));
    EXPECT_EQ(three.lookAt.center, Vec3<double>(0, 0, 0));

    // The look-at call's suffix decides the handedness, over the projection call's.
    EXPECT_EQ(applyCode(camera, "glm::perspectiveRH_ZO(1.0f, 1.5f, 0.1f, 100.0f);\n"
                                      "glm::lookAtLH(glm::vec3(1, 2, 3), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));")
                  .handedness,
              gl::Handedness::Left);
    EXPECT_EQ(applyCode(camera, "glm::perspectiveLH_ZO(1.0f, 1.5f, 0.1f, 100.0f);").handedness,
              gl::Handedness::Left);

    // A look-at alone keeps the projection.
    const Camera look = applyCode(camera, "XMMatrixLookAtRH(XMVectorSet(1, 2, 3, 1), XMVectorSet(0, 0, 0, 1), "
                                                "XMVectorSet(0, 1, 0, 0));");
    EXPECT_EQ(look.lookAt.eye, Vec3<double>(1, 2, 3));
    EXPECT_EQ(gl::projectionMatrix(look), gl::projectionMatrix(camera));
}

// A drag's steps, the app's and the page's: a two-hundredth of the size as a power of ten, whole steps exactly.
TEST(CameraCode, ANumberStepsByAPowerOfTenExactly)
{
    EXPECT_EQ(stepFor(40), 0.1);
    EXPECT_EQ(steppedValue(40, 50), 45);
    EXPECT_EQ(steppedValue(40, 3), 40.3); // not 40.300000000000004
    EXPECT_EQ(steppedValue(0.5, -1), 0.499);
    EXPECT_EQ(steppedValue(1000, 1), 1001);
    EXPECT_EQ(steppedValue(std::numeric_limits<double>::infinity(), 5), std::numeric_limits<double>::infinity());
}

} // namespace
} // namespace viewpipe::report
