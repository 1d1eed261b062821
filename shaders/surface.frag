#version 330 core
// Two-sided Blinn-Phong with a key and a fill light fixed to the camera.
//
// isotrack's normals point from above the isovalue to below it, i.e. out of the
// object, and triangles wind counter-clockwise seen from outside, so front faces
// are the outside. Back faces (the inside, seen through an open border) use the
// flipped normal and a darker colour so the two sides read differently.

in vec3 vPositionView;
in vec3 vNormalView;
in float vGrowth;  // 0 at the seed .. 1 at the newest vertex, when colouring by growth
flat in vec3 vColour;
flat in float vHighlight;  // 1 for the selected surface, else 0
flat in float vGrowthScale;  // > 0: colour by growth order instead of vColour

out vec4 fragColour;

const vec3 kKeyDirection = vec3(-0.35, 0.55, 0.76);   // towards the light, view space
const vec3 kFillDirection = vec3(0.62, -0.28, 0.73);
const float kAmbient = 0.16;
const float kFill = 0.30;
const float kSpecular = 0.28;
const float kShininess = 48.0;
const float kBackSideDarkening = 0.62;
const vec3 kHighlightColour = vec3(1.0, 1.0, 0.92);
const float kStripePeriod = 10.0;  // pixels

// Dark violet (first reached) through teal to yellow (last reached).
vec3 growthColour(float t) {
    const vec3 first = vec3(0.28, 0.05, 0.40);
    const vec3 middle = vec3(0.13, 0.57, 0.55);
    const vec3 last = vec3(0.99, 0.91, 0.14);
    t = clamp(t, 0.0, 1.0);
    return t < 0.5 ? mix(first, middle, 2.0 * t) : mix(middle, last, 2.0 * t - 1.0);
}

float diffuse(vec3 n, vec3 l) { return max(dot(n, l), 0.0); }

float specular(vec3 n, vec3 l, vec3 v) {
    vec3 h = normalize(l + v);
    return pow(max(dot(n, h), 0.0), kShininess);
}

void main() {
    vec3 n = normalize(vNormalView);
    vec3 albedo = vColour;
    if (vGrowthScale > 0.0) albedo = growthColour(vGrowth);
    if (!gl_FrontFacing) {
        n = -n;
        albedo *= kBackSideDarkening;
    }
    vec3 v = normalize(-vPositionView);
    vec3 key = normalize(kKeyDirection);
    vec3 fill = normalize(kFillDirection);

    vec3 colour = albedo * (kAmbient + diffuse(n, key) + kFill * diffuse(n, fill));
    colour += vec3(kSpecular * specular(n, key, v));

    // The selection glows white at its silhouette and carries diagonal stripes in
    // screen space: recognisable whatever its own colour is.
    float rim = pow(1.0 - max(dot(n, v), 0.0), 1.5);
    float stripe = step(mod(gl_FragCoord.x + gl_FragCoord.y, kStripePeriod), 0.5 * kStripePeriod);
    colour = mix(colour, kHighlightColour, vHighlight * (0.12 + 0.30 * stripe + 0.70 * rim));

    fragColour = vec4(min(colour, vec3(1.0)), 1.0);
}
