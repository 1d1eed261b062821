#include "render/camera.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <vector>

#include "isotrack/errors.h"

namespace isotrack::render {
namespace {

constexpr glm::vec3 kUp{0.0f, 0.0f, 1.0f};
constexpr float kMinFov = 1.0f, kMaxFov = 170.0f;
constexpr float kFrameMargin = 1.06f;  // a little air between the box and the image border

glm::vec3 viewDirectionToEye(const Camera& camera) {
    const float yaw = glm::radians(camera.yaw), pitch = glm::radians(camera.pitch);
    return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
}

std::vector<std::string> splitFields(const std::string& text) {
    std::vector<std::string> fields(1);
    for (char c : text) {
        if (c == ',') {
            fields.emplace_back();
        } else if (c != ' ') {
            fields.back() += c;
        }
    }
    return fields;
}

float parseNumber(const std::string& field, const char* name, const std::string& text) {
    float value = 0.0f;
    const char* end = field.data() + field.size();
    const auto [ptr, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || error != std::errc() || ptr != end || !std::isfinite(value)) {
        throw InputError("camera \"" + text + "\": " + name + " \"" + field + "\" is not a finite number");
    }
    return value;
}

void appendNumber(std::string& out, float value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    if (!out.empty()) out += ',';
    out.append(buffer, result.ptr);
}

}  // namespace

float Bounds::radius() const { return 0.5f * glm::length(max - min); }

glm::vec3 Camera::eye() const { return target + distance * viewDirectionToEye(*this); }

glm::mat4 Camera::view() const { return glm::lookAt(eye(), target, kUp); }

glm::mat4 Camera::projection(float aspect, float near, float far) const {
    return glm::perspective(glm::radians(fov), aspect, near, far);
}

void Camera::orbit(float yawDegrees, float pitchDegrees) {
    yaw = std::remainder(yaw + yawDegrees, 360.0f);
    pitch = std::clamp(pitch + pitchDegrees, -kMaxPitch, kMaxPitch);
}

void Camera::zoom(float factor) {
    if (factor > 0.0f && std::isfinite(factor)) distance *= factor;
}

void Camera::pan(float right, float up) {
    const glm::vec3 forward = -viewDirectionToEye(*this);
    const glm::vec3 rightAxis = glm::normalize(glm::cross(forward, kUp));
    const glm::vec3 upAxis = glm::cross(rightAxis, forward);
    target += (rightAxis * right + upAxis * up) * distance;
}

Camera frameBounds(const Bounds& bounds, float aspect) {
    Camera camera;
    camera.target = bounds.centre();
    // The nearest distance at which every corner of the box lies inside the
    // frustum: a corner at (x, y) across the view and z towards the eye needs
    // distance >= z + |x| / tan(half horizontal fov), and likewise for y.
    const glm::vec3 back = viewDirectionToEye(camera);
    const glm::vec3 right = glm::normalize(glm::cross(-back, kUp));
    const glm::vec3 up = glm::cross(right, -back);
    const float tanVertical = std::tan(glm::radians(camera.fov) * 0.5f);
    const float tanHorizontal = tanVertical * aspect;
    float distance = 1e-3f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner{(i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z};
        const glm::vec3 d = corner - camera.target;
        const float z = glm::dot(d, back);
        distance = std::max(
            {distance, z + std::abs(glm::dot(d, right)) / tanHorizontal, z + std::abs(glm::dot(d, up)) / tanVertical});
    }
    camera.distance = distance * kFrameMargin;
    return camera;
}

void clipPlanes(const Camera& camera, const Bounds& bounds, float& near, float& far) {
    const float radius = std::max(bounds.radius(), 1e-3f) * 1.01f;
    const float toCentre = glm::length(camera.eye() - bounds.centre());
    far = toCentre + radius;
    near = std::max(toCentre - radius, far * 1e-4f);
}

std::string formatCamera(const Camera& camera) {
    std::string out;
    for (float value :
         {camera.yaw, camera.pitch, camera.distance, camera.target.x, camera.target.y, camera.target.z, camera.fov}) {
        appendNumber(out, value);
    }
    return out;
}

Camera parseCamera(const std::string& text) {
    const std::vector<std::string> fields = splitFields(text);
    if (fields.size() != 6 && fields.size() != 7) {
        throw InputError("camera \"" + text + "\": expected yaw,pitch,distance,tx,ty,tz[,fov], got " +
                         std::to_string(fields.size()) + " fields");
    }
    static const char* const names[] = {"yaw", "pitch", "distance", "tx", "ty", "tz", "fov"};
    float values[7] = {0, 0, 0, 0, 0, 0, Camera::kDefaultFov};
    for (std::size_t i = 0; i < fields.size(); ++i) values[i] = parseNumber(fields[i], names[i], text);

    Camera camera;
    camera.yaw = values[0];
    camera.pitch = values[1];
    camera.distance = values[2];
    camera.target = {values[3], values[4], values[5]};
    camera.fov = values[6];
    if (std::abs(camera.pitch) > Camera::kMaxPitch) {
        throw InputError("camera \"" + text + "\": pitch " + fields[1] + " is outside -89..89");
    }
    if (!(camera.distance > 0.0f)) {
        throw InputError("camera \"" + text + "\": distance " + fields[2] + " must be positive");
    }
    if (camera.fov < kMinFov || camera.fov > kMaxFov) {
        throw InputError("camera \"" + text + "\": fov " + fields.back() + " is outside 1..170");
    }
    return camera;
}

}  // namespace isotrack::render
