// camera.cpp — orbit, zoom, pan and framing.
#include "core/scene/camera.h"

#include "core/scene/limits.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lab {

void keepCameraValid(Camera& camera) {
    constexpr float kMinDistance = 2.0f * limits::kMinDirectionLength; // twice the validator's, for rounding
    const glm::vec3 margin(kMinDistance);
    camera.target = glm::clamp(camera.target, glm::vec3(limits::kCoordinate.min) + margin,
                               glm::vec3(limits::kCoordinate.max) - margin);
    glm::vec3 offset = camera.eye - camera.target;
    float distance = glm::length(offset);
    if (!(distance >= kMinDistance)) { // too close (or not a number): the same direction, farther
        offset = distance > 0.0f ? offset / distance : glm::vec3(0.0f, 0.0f, 1.0f);
        camera.eye = camera.target + offset * kMinDistance;
    }
    camera.eye = glm::clamp(camera.eye, glm::vec3(limits::kCoordinate.min), glm::vec3(limits::kCoordinate.max));
}

void orbitCamera(Camera& camera, float yawDeg, float pitchDeg) {
    glm::vec3 up = glm::normalize(camera.up);
    glm::vec3 offset = camera.eye - camera.target;
    float distance = glm::length(offset);
    glm::vec3 dir = offset / distance;
    // Yaw about the up axis.
    dir = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(yawDeg), up) * glm::vec4(dir, 0.0f));
    // Pitch about the right axis, clamped so that the direction stays 1 degree from the up axis.
    float current = glm::degrees(std::acos(std::clamp(glm::dot(dir, up), -1.0f, 1.0f))); // 0 = above the target
    float target = std::clamp(current - pitchDeg, 1.0f, 179.0f);
    glm::vec3 right = glm::cross(dir, up); // turning about it by a positive angle raises dir towards up
    if (glm::length(right) > 1e-6f) {
        right = glm::normalize(right);
        dir = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(current - target), right) * glm::vec4(dir, 0.0f));
    }
    camera.eye = camera.target + glm::normalize(dir) * distance;
    keepCameraValid(camera);
}

void zoomCamera(Camera& camera, float factor) {
    glm::vec3 offset = camera.eye - camera.target;
    float distance = glm::length(offset);
    float next = std::clamp(distance * factor, camera.near * 2.0f, camera.far / 2.0f);
    camera.eye = camera.target + offset * (next / distance);
    keepCameraValid(camera);
}

void panCamera(Camera& camera, float dx, float dy) {
    glm::vec3 forward = camera.target - camera.eye;
    float distance = glm::length(forward);
    forward /= distance;
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    float viewSide = 2.0f * distance * std::tan(glm::radians(camera.fovyDeg) / 2.0f); // the narrower side's extent
    glm::vec3 move = (-dx * right - dy * up) * viewSide;
    camera.eye += move;
    camera.target += move;
    keepCameraValid(camera);
}

//----------------------------------------------------------------------------------------
// Framing
//----------------------------------------------------------------------------------------

namespace {

constexpr float kFramedShare = 0.85f;       // of the view's narrower side that the projected points span
constexpr float kMinFramedRadius = 1.0e-3f; // smaller models are framed as this half diagonal (near stays in range)
constexpr float kMaxFramedRadius = 1.0e7f;  // (a finite bound for the arithmetic; such a model cannot be framed anyway)
constexpr float kMinProjectedShare = 1.0e-3f; // of the half diagonal: less projected size is framed as the box
constexpr int kBisections = 32;

// The view's axes: x right, y up, z forward (from the eye towards the target).
struct ViewBasis {
    glm::vec3 right, up, forward;
    glm::vec3 toView(glm::vec3 v) const { return {glm::dot(v, right), glm::dot(v, up), glm::dot(v, forward)}; }
    glm::vec3 toWorld(glm::vec3 v) const { return v.x * right + v.y * up + v.z * forward; }
};

ViewBasis viewBasis(glm::vec3 direction, glm::vec3 up, bool& upParallel) {
    ViewBasis b;
    b.forward = -direction;
    glm::vec3 right = glm::cross(b.forward, up);
    upParallel = !(glm::length(right) > 1e-6f * glm::length(up));
    if (upParallel) { // looking along up: any right angle will do
        right = glm::cross(b.forward, std::abs(b.forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
    }
    b.right = glm::normalize(right);
    b.up = glm::cross(b.right, b.forward);
    return b;
}

// For points `q` in the view's basis and an image axis (0: x, 1: y) seen at the tangent `t`
// either side of the view's centre: the largest q[axis] - t q.z and the smallest q[axis] + t q.z.
// An eye at (e, ez) on that axis sees every point within ±t when e - t ez >= hi and e + t ez <= lo.
struct Planes {
    float hi, lo;
};

Planes planes(std::span<const glm::vec3> q, int axis, float t) {
    Planes p{-limits::kUnbounded, limits::kUnbounded};
    for (const glm::vec3& c : q) {
        p.hi = std::max(p.hi, c[axis] - t * c.z);
        p.lo = std::min(p.lo, c[axis] + t * c.z);
    }
    return p;
}

// The eye's offset along `axis` that centres the points' projections seen from depth `ez` (behind
// every point): both sides touch at the tangent t where hi(t) - lo(t) + 2 t ez = 0, whose left
// side falls with t (from the points' width at t = 0 to at most 0 at `tMax`); bisected.
float centred(std::span<const glm::vec3> q, int axis, float ez, float tMax) {
    float lo = 0.0f, hi = tMax;
    for (int i = 0; i < kBisections; ++i) {
        float t = 0.5f * (lo + hi);
        Planes p = planes(q, axis, t);
        (p.hi - p.lo + 2.0f * t * ez > 0.0f ? lo : hi) = t;
    }
    return planes(q, axis, hi).hi + hi * ez;
}

// Where the eye stands (view basis) for the points `q` to span `share` of a view whose half
// narrower side has tangent `tanHalf`, centred. Each image axis alone would fit from depth
// ez = (lo - hi) / (2 s) at s = share · tanHalf, which lies behind every point (lo - hi <= 2 s q.z
// for each); the larger projected dimension decides: the nearer of the two depths would cut the
// other axis.
glm::vec3 fittedEye(std::span<const glm::vec3> q, float share, float tanHalf) {
    float s = share * tanHalf;
    Planes x = planes(q, 0, s), y = planes(q, 1, s);
    float ez = std::min((x.lo - x.hi) / (2.0f * s), (y.lo - y.hi) / (2.0f * s));
    return {centred(q, 0, ez, s), centred(q, 1, ez, s), ez};
}

// The points of `q` that the two functions above can meet: for each image axis, the vertices of
// the convex hull of (q.z, q[axis]), where every linear function of the two is largest and
// smallest. Points inside the octagon of the extremes in 8 directions are no vertices (Akl and
// Toussaint 1978); Andrew's monotone chain (1979) finds the hull of the rest. A mesh of a
// million triangles keeps a few hundred points.
std::vector<glm::vec3> hullPoints(const std::vector<glm::vec3>& q) {
    struct Point {
        glm::vec2 p; // (z, q[axis])
        std::uint32_t index;
    };
    auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<char> kept(q.size(), 0);
    std::vector<Point> points;
    std::vector<Point> chain;
    for (int axis = 0; axis < 2; ++axis) {
        // The extremes in 8 directions, counter-clockwise.
        std::array<glm::vec2, 8> extreme;
        std::array<float, 8> best;
        best.fill(-limits::kUnbounded);
        for (const glm::vec3& v : q) {
            glm::vec2 p(v.z, v[axis]);
            const std::array<float, 8> along = {p.x, p.x + p.y, p.y, p.y - p.x, -p.x, -p.x - p.y, -p.y, p.x - p.y};
            for (std::size_t k = 0; k < 8; ++k) {
                if (along[k] > best[k]) {
                    best[k] = along[k];
                    extreme[k] = p;
                }
            }
        }
        points.clear();
        for (std::size_t i = 0; i < q.size(); ++i) {
            glm::vec2 p(q[i].z, q[i][axis]);
            bool inside = true;
            for (std::size_t k = 0; k < 8 && inside; ++k) {
                glm::vec2 a = extreme[k], b = extreme[(k + 1) % 8];
                inside = a == b || cross(a, b, p) > 0.0f; // (a repeated extreme is no edge)
            }
            if (!inside) {
                points.push_back({p, static_cast<std::uint32_t>(i)});
            }
        }
        std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
            return a.p.x < b.p.x || (a.p.x == b.p.x && a.p.y < b.p.y);
        });
        for (int pass = 0; pass < 2; ++pass) { // the lower chain, then the upper
            chain.clear();
            for (std::size_t k = 0; k < points.size(); ++k) {
                const Point& next = points[pass == 0 ? k : points.size() - 1 - k];
                while (chain.size() >= 2 && cross(chain[chain.size() - 2].p, chain.back().p, next.p) <= 0.0f) {
                    chain.pop_back();
                }
                chain.push_back(next);
            }
            for (const Point& p : chain) {
                kept[p.index] = 1;
            }
        }
    }
    std::vector<glm::vec3> hull;
    for (std::size_t i = 0; i < q.size(); ++i) {
        if (kept[i]) {
            hull.push_back(q[i]);
        }
    }
    return hull;
}

bool inCoordinateRange(glm::vec3 p) {
    return glm::all(glm::greaterThanEqual(p, glm::vec3(limits::kCoordinate.min))) &&
           glm::all(glm::lessThanEqual(p, glm::vec3(limits::kCoordinate.max)));
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The 8 corners of the box from centre - half to centre + half.
std::vector<glm::vec3> boxCorners(glm::vec3 center, glm::vec3 half) {
    std::vector<glm::vec3> corners;
    for (int i = 0; i < 8; ++i) { // bit 0: +x, bit 1: +y, bit 2: +z
        corners.push_back(center + half * glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f));
    }
    return corners;
}

// What framing fits in the view: `points` relative to `center` (the centre of their box) in the
// view's basis, the outline only (hullPoints). A box stands in for points too small (or too
// large) to frame as they are, or that project to (almost) nothing; none, or any not finite, are
// the smallest box at the base's target.
std::vector<glm::vec3> pointsToFrame(std::span<const glm::vec3> points, const ViewBasis& basis, const Camera& base,
                                     glm::vec3& center) {
    glm::vec3 lo(limits::kUnbounded), hi(-limits::kUnbounded);
    bool usable = !points.empty();
    for (const glm::vec3& p : points) {
        usable = usable && finite(p);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    center = lo * 0.5f + hi * 0.5f; // (halves first: no overflow)
    glm::vec3 half = hi * 0.5f - lo * 0.5f;
    float radius = usable ? glm::length(half) : 0.0f;
    if (!usable) {
        Camera kept = base;
        keepCameraValid(kept);
        center = kept.target;
    }
    std::vector<glm::vec3> q;
    if (!(radius >= kMinFramedRadius)) {
        q = boxCorners(glm::vec3(0.0f), glm::vec3(kMinFramedRadius / std::sqrt(3.0f)));
    } else if (!(radius <= kMaxFramedRadius)) {
        half = glm::min(half, glm::vec3(kMaxFramedRadius / std::sqrt(3.0f)));
        radius = glm::length(half);
        q = boxCorners(glm::vec3(0.0f), half);
    } else {
        q.reserve(points.size());
        for (const glm::vec3& p : points) {
            q.push_back(p - center);
        }
    }
    for (glm::vec3& v : q) {
        v = basis.toView(v);
    }
    q = hullPoints(q);
    Planes x = planes(q, 0, 0.0f), y = planes(q, 1, 0.0f);
    if (std::max(x.hi - x.lo, y.hi - y.lo) < 2.0f * kMinProjectedShare * radius) {
        q = boxCorners(glm::vec3(0.0f), glm::max(half, glm::vec3(kMinProjectedShare * radius)));
        for (glm::vec3& v : q) {
            v = basis.toView(v);
        }
    }
    return q;
}

} // namespace

glm::vec3 threeQuarterDirection() {
    constexpr float kAzimuthDeg = 35.0f, kElevationDeg = 25.0f;
    float azimuth = glm::radians(kAzimuthDeg), elevation = glm::radians(kElevationDeg);
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

Camera framedCamera(const Camera& base, std::span<const glm::vec3> points) {
    return framedCamera(base, points, base.eye - base.target);
}

Camera framedCamera(const Camera& base, std::span<const glm::vec3> points, glm::vec3 direction) {
    Camera c = base;
    float length = glm::length(direction);
    glm::vec3 dir = length > 0.0f && std::isfinite(length) ? direction / length : glm::vec3(0.0f, 0.0f, 1.0f);
    bool upParallel = false;
    const ViewBasis basis = viewBasis(dir, base.up, upParallel);
    if (upParallel) {
        c.up = basis.up; // (the validator refuses an up along the view)
    }

    glm::vec3 center;
    const std::vector<glm::vec3> q = pointsToFrame(points, basis, base, center);

    // fovy_deg spans the view's narrower side whatever its shape (core/lighting/lighting.h).
    auto eyeAt = [&](float fovyDeg) {
        return center + basis.toWorld(fittedEye(q, kFramedShare, std::tan(glm::radians(fovyDeg) * 0.5f)));
    };
    c.fovyDeg = limits::clamp(limits::kFovyDeg, base.fovyDeg);
    if (!inCoordinateRange(eyeAt(c.fovyDeg)) && inCoordinateRange(eyeAt(limits::kFovyDeg.max))) {
        // Too far for the range: nearer, with a wider view (the least that keeps the eye inside).
        float narrow = c.fovyDeg, wide = limits::kFovyDeg.max;
        for (int i = 0; i < kBisections; ++i) {
            float mid = 0.5f * (narrow + wide);
            (inCoordinateRange(eyeAt(mid)) ? wide : narrow) = mid;
        }
        c.fovyDeg = wide;
    }
    glm::vec3 e = fittedEye(q, kFramedShare, std::tan(glm::radians(c.fovyDeg) * 0.5f));
    c.eye = center + basis.toWorld(e);
    c.target = center + basis.toWorld({e.x, e.y, 0.0f}); // on the axis, at the depth of the box's centre
    float distance = -e.z;
    float nearest = limits::kUnbounded, farthest = 0.0f;
    for (const glm::vec3& v : q) {
        nearest = std::min(nearest, v.z - e.z);
        farthest = std::max(farthest, v.z - e.z);
    }
    // The default camera's ratios: near 0.1 and far 100 at a distance of 4; near closer when a
    // point is (a long model seen end on), far farther.
    c.near = limits::clamp(limits::kNear, std::min(distance / 40.0f, nearest / 2.0f));
    c.far = std::max(limits::clamp(limits::kFar, std::max(distance * 25.0f, farthest * 2.0f)), limits::nextUp(c.near));
    keepCameraValid(c);
    return c;
}

} // namespace lab
