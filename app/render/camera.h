#pragma once
// An orbit camera: it looks at `target` from `distance` away, turned `yaw`
// degrees about the world z axis (from +x towards +y) and raised `pitch` degrees
// above the xy plane; z is up on screen. `fov` is the vertical field of view.
//
// As text (--camera on the command line, and what isotrack prints back):
//   yaw,pitch,distance,tx,ty,tz[,fov]
// degrees and world units, comma-separated, fov defaulting to 30. formatCamera
// writes each number in the shortest form that reads back exactly, so
// parseCamera(formatCamera(c)) == c.
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace isotrack::render {

struct Bounds {
    glm::vec3 min{0.0f}, max{0.0f};
    glm::vec3 centre() const { return (min + max) * 0.5f; }
    float radius() const;  // of the bounding sphere
};

struct Camera {
    static constexpr float kDefaultYaw = -60.0f;
    static constexpr float kDefaultPitch = 22.0f;
    static constexpr float kDefaultFov = 30.0f;
    static constexpr float kMaxPitch = 89.0f;

    float yaw = kDefaultYaw;      // degrees
    float pitch = kDefaultPitch;  // degrees, within +-kMaxPitch
    float distance = 1.0f;        // from the target, > 0
    glm::vec3 target{0.0f};
    float fov = kDefaultFov;  // degrees, vertical

    glm::vec3 eye() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect, float near, float far) const;

    // Interaction for a viewer: turn about the target, dolly, slide the target
    // across the screen (right and up in view units of `distance`).
    void orbit(float yawDegrees, float pitchDegrees);
    void zoom(float factor);
    void pan(float right, float up);

    friend bool operator==(const Camera& a, const Camera& b) {
        return a.yaw == b.yaw && a.pitch == b.pitch && a.distance == b.distance && a.target == b.target &&
               a.fov == b.fov;
    }
};

// The default view of `bounds` for an image of the given aspect (width/height):
// the default angles, looking at the centre, as close as possible with all of
// the box in view, plus a small margin.
Camera frameBounds(const Bounds& bounds, float aspect);

// Near and far planes that hold all of `bounds` as seen from `camera`.
void clipPlanes(const Camera& camera, const Bounds& bounds, float& near, float& far);

std::string formatCamera(const Camera& camera);
// Throws isotrack::InputError naming the text and the field at fault.
Camera parseCamera(const std::string& text);

}  // namespace isotrack::render
