#pragma once

// The camera as code: what a program in each dialect writes to get the
// camera's view and projection matrices, with every number that stands for a
// camera parameter located in the text (for the app's Code panel to drag and
// edit), and the reverse: a pasted call sets the camera.

#include <string>
#include <vector>

#include "viewpipe/gl.hpp"

namespace viewpipe::report {

enum class Dialect { OpenGL, Glm, DirectXMath, ThreeJs, WgpuMatrix };

inline constexpr Dialect kDialects[] = {Dialect::OpenGL, Dialect::Glm, Dialect::DirectXMath, Dialect::ThreeJs,
                                        Dialect::WgpuMatrix};

// "opengl", "glm", "directxmath", "threejs", "wgpu-matrix": as --dialect names it.
std::string dialectName(Dialect dialect);
// "Legacy OpenGL", "glm", "DirectXMath", "three.js", "wgpu-matrix": as people name it.
std::string dialectTitle(Dialect dialect);
// The dialect called `name`; throws InputError(field, ...) naming the known ones.
Dialect dialectNamed(const std::string& name, const std::string& field);

// One number in the code that stands for a camera parameter.
struct CodeNumber {
    std::size_t offset = 0, length = 0; // the number's characters in CameraCode::text
    std::string field;                  // the scene field it is: "camera.look_at.eye[0]", "camera.projection.fovy_deg"
    double value = 0;                   // the field's value (the code shows this number)
    std::string tooltip;                // what it is, with its unit: "fovy: vertical field of view, in degrees"
};

struct CameraCode {
    std::string text;
    std::vector<CodeNumber> numbers; // in the order they appear
};

// The code that gives exactly this camera's view and projection matrices
// (its API, handedness and depth included) in the dialect.
CameraCode cameraCode(const gl::Camera<double>& camera, Dialect dialect);

// A number dragged or stepped `steps` steps from `from`: whole steps of a
// two-hundredth of its size (at least of 1) as a power of ten, so 40 moves by
// 0.1 (to 40.3, not 40.300000000000004) and 0.5 by 0.001. An infinite number stays.
double steppedValue(double from, int steps);
// The step of steppedValue.
double stepFor(double value);

// The camera with one field set (a CodeNumber's field); throws InputError naming
// the field when the value makes no valid camera.
gl::Camera<double> withField(const gl::Camera<double>& camera, const std::string& field, double value);

// The camera with what pasted code sets: a projection call (gluPerspective(45,
// 1.333, 0.1, 100), XMMatrixPerspectiveFovLH(XM_PIDIV4, 16.f/9.f, 0.1f,
// 100.f), glm::perspective(glm::radians(45.0f), ...), new
// THREE.PerspectiveCamera(...), mat4.perspective(...)) and/or a look-at call.
// Throws InputError("code", ...) when nothing is recognized or a value is bad.
gl::Camera<double> applyCode(const gl::Camera<double>& camera, const std::string& code);

} // namespace viewpipe::report
