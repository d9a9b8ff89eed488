#include "viewpipe/precision_ladder.hpp"

#include <algorithm>
#include <chrono>

#include "viewpipe/exact.hpp"
#include "viewpipe/format.hpp"

namespace viewpipe {
namespace {

using Clock = std::chrono::steady_clock;

template <class F> double nanoseconds(F&& f)
{
    const auto start = Clock::now();
    f();
    return std::chrono::duration<double, std::nano>(Clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// Points inside the view volume, x, y, z interleaved.
std::vector<double> volumePoints(const ReferenceSolution& ref, std::size_t count)
{
    std::vector<double> points;
    points.reserve(3 * count);
    for (const Vec3<double>& p : pointsInside(ref.corners, count, 7))
        points.insert(points.end(), {p.x(), p.y(), p.z()});
    return points;
}

// Repetitions: enough for a stable median, fewer for the slow wide types.
int repeatsFor(int bits)
{
    return bits <= 64 ? 7 : 3;
}

BenchRow tierRow(const std::string& name, int bits)
{
    BenchRow row;
    row.precision = name;
    row.bits = bits;
    row.epsilon = std::ldexp(1.0, 1 - bits);
    return row;
}

// Median time to build the pipeline in T.
template <class T> double buildNanoseconds(const CameraSpec<double>& camera, int bits)
{
    const int builds = bits <= 64 ? 2000 : 200;
    std::vector<double> times;
    for (int r = 0; r < repeatsFor(bits); ++r)
        times.push_back(nanoseconds([&] {
                            for (int b = 0; b < builds; ++b) {
                                const Pipeline<T> p = buildPipeline(castCamera<T>(camera));
                                asm volatile("" : : "g"(&p) : "memory");
                            }
                        }) /
                        builds);
    return median(times);
}

template <class T> BenchRow timeTier(const std::string& name, int bits, const CameraSpec<double>& camera,
                                     const std::vector<double>& points)
{
    BenchRow row = tierRow(name, bits);
    row.buildNs = buildNanoseconds<T>(camera, bits);
    const Pipeline<T> p = buildPipeline(castCamera<T>(camera));
    const Mat4<T> clip = p.clipMatrix();
    const std::size_t count = points.size() / 3;
    std::vector<T> in(points.begin(), points.end()), out(points.size());
    std::vector<double> times;
    for (int r = 0; r < repeatsFor(bits); ++r)
        times.push_back(nanoseconds([&] { transformPoints(clip, in.data(), out.data(), count); }) / double(count));
    row.vertexNs = median(times);
    return row;
}

BenchRow timeDoubleDouble(const CameraSpec<double>& camera, const std::vector<double>& points)
{
    BenchRow row = tierRow("double-double", 106);
    row.buildNs = buildNanoseconds<Float128>(camera, 106); // built in binary128
    const Pipeline<Float128> p = buildPipeline(castCamera<Float128>(camera));
    const Mat4DD clip = toDoubleDouble(Mat4<Float128>(p.clipMatrix()));
    const std::size_t count = points.size() / 3;
    std::vector<double> hi(points.size()), lo(points.size());
    std::vector<double> times;
    for (int r = 0; r < repeatsFor(64); ++r)
        times.push_back(nanoseconds([&] { transformPointsDoubleDouble(clip, points.data(), hi.data(), lo.data(), count); }) /
                        double(count));
    row.vertexNs = median(times);
    return row;
}

// The exact type computes the scene as typed (its decimals and expressions),
// with no error: its cost is timed on fewer vertices, as it is per vertex.
BenchRow timeExact(const Scene& scene, const std::vector<double>& points)
{
    BenchRow row = tierRow("exact", 0);
    row.epsilon = 0;
    constexpr int kBuilds = 20;
    std::vector<double> times;
    for (int r = 0; r < 3; ++r)
        times.push_back(nanoseconds([&] {
                            for (int b = 0; b < kBuilds; ++b) {
                                const Pipeline<Exact> p = exactPipeline(scene);
                                asm volatile("" : : "g"(&p) : "memory");
                            }
                        }) /
                        kBuilds);
    row.buildNs = median(times);
    const Mat4<Exact> clip = exactPipeline(scene).clipMatrix();
    const std::size_t count = std::min<std::size_t>(points.size() / 3, 2000);
    times.clear();
    for (int r = 0; r < 3; ++r)
        times.push_back(nanoseconds([&] {
                            for (std::size_t i = 0; i < count; ++i) {
                                const Vec4<Exact> h = clip * Vec4<Exact>(Exact(points[3 * i]), Exact(points[3 * i + 1]),
                                                                         Exact(points[3 * i + 2]), Exact(1));
                                const Vec3<Exact> divided = h.head<3>() / h.w();
                                asm volatile("" : : "g"(&divided) : "memory");
                            }
                        }) /
                        double(count));
    row.vertexNs = median(times);
    return row;
}

// How far the reference's composite (from the scene's numbers as doubles) is
// from the exact composite of the scene as typed, relative to its largest entry.
double typedAgreement(const ReferenceSolution& ref, const Scene& scene)
{
    const Mat4<Exact> exact = exactPipeline(scene).composite;
    setReferenceBits(ref.bits);
    Reference worst = 0;
    const Reference scale = ref.pipeline.composite.cwiseAbs().maxCoeff();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            worst = std::max<Reference>(
                worst, abs(Reference(exact(r, c).approximation().str(50)) - ref.pipeline.composite(r, c)) / scale);
    return static_cast<double>(worst);
}

} // namespace

BenchResult runBench(const Scene& scene, const std::vector<Vec3<double>>& sceneVertices, const BenchOptions& options,
                     const BenchProgress& progress)
{
    if (options.vertices < 1 || options.vertices > 100000000)
        throw InputError("--vertices", "must be 1 to 100000000");
    if (options.mpfrBits < 16 || options.mpfrBits > 4096)
        throw InputError("--bits", "must be 16 to 4096");
    BenchResult result;
    result.vertices = options.vertices;
    result.viewport = options.viewport;
    const ReferenceSolution ref = makeReference(scene.camera, 256);
    const double agreement = referenceAgreement(ref, makeReference(scene.camera, 512));
    result.reference = "mpfr-256 (agrees with mpfr-512 to " + formatSignificant(agreement, 2) +
                       ", with the exact composite of the scene as typed to " +
                       formatSignificant(typedAgreement(ref, scene), 2) + ")";
    if (ref.farStandIn)
        result.volume = "the view volume up to far = " + formatSignificant(gl::kStandInFar, 4) +
                        " × near (its far plane is infinite)";
    const std::vector<double> points = volumePoints(ref, options.vertices);
    const int total = 7;
    int done = 0;
    auto next = [&](const std::string& tier) { return !progress || progress(done++, total, tier); };
    const Viewport& vp = options.viewport;
    const CameraSpec<double>& camera = scene.camera;

    if (next("float")) {
        result.rows.push_back(timeTier<float>("float", 24, camera, points));
        result.rows.back().errors = measureAccuracy<float>(camera, sceneVertices, ref, vp);
    }
    if (next("double")) {
        result.rows.push_back(timeTier<double>("double", 53, camera, points));
        result.rows.back().errors = measureAccuracy<double>(camera, sceneVertices, ref, vp);
    }
    if (next("long-double")) {
        result.rows.push_back(timeTier<long double>("long-double", 64, camera, points));
        result.rows.back().errors = measureAccuracy<long double>(camera, sceneVertices, ref, vp);
    }
    if (next("double-double")) {
        result.rows.push_back(timeDoubleDouble(camera, points));
        result.rows.back().errors = measureDoubleDoubleAccuracy(camera, sceneVertices, ref, vp);
    }
    if (next("float128")) {
        result.rows.push_back(timeTier<Float128>("float128", 113, camera, points));
        result.rows.back().errors = measureAccuracy<Float128>(camera, sceneVertices, ref, vp);
    }
    if (next("mpfr")) {
        setReferenceBits(options.mpfrBits);
        // Mpfr values made now carry the chosen precision; the reference keeps its own.
        result.rows.push_back(timeTier<Mpfr>("mpfr", int(options.mpfrBits), camera, points));
        result.rows.back().errors = measureAccuracy<Mpfr>(camera, sceneVertices, ref, vp);
    }
    if (next("exact"))
        result.rows.push_back(timeExact(scene, points)); // errors 0: it is the scene as typed
    if (progress)
        progress(total, total, "");
    return result;
}

} // namespace viewpipe
