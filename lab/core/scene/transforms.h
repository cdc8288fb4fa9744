// transforms.h — the scene's matrices: model, view, projection and the normal matrix.
//
// What the renderer, the pixel probe, the plots at the probe, the viewport's captions and the model
// loader's framing all compute from a Preset's model and camera. It does not shade anything
// (core/lighting) or frame a camera on a model (camera.h).
#pragma once

#include "core/scene/preset.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace lab {

struct Transforms {
    glm::mat4 model;
    glm::mat4 view;
    glm::mat4 projection;
    glm::mat4 modelView;
    glm::mat3 normalMatrix; // per the preset's normal_matrix mode
};

// Model = T·Rz·Ry·Rx·S; view = lookAt; projection = perspective(vertical field of view, aspect, near,
// far), where the camera's fovy_deg is the field of view of the view's narrower side: vertical when
// the view is at least as wide as tall (aspect = width / height >= 1), horizontal when it is taller
// than wide (Blender's sensor fit "auto"), so what a camera frames stays whole in any shape.
glm::mat4 modelMatrix(const Model& model);
float verticalFovRadians(const Camera& camera, float aspect);
glm::mat4 projectionMatrix(const Camera& camera, float aspect);
Transforms computeTransforms(const Preset& preset, float aspect);

} // namespace lab
