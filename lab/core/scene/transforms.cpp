// transforms.cpp — the scene's matrices (transforms.h).
#include "core/scene/transforms.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace lab {

glm::mat4 modelMatrix(const Model& model) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), model.translate);
    m = glm::rotate(m, glm::radians(model.rotateDeg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(model.rotateDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(model.rotateDeg.x), glm::vec3(1, 0, 0));
    return glm::scale(m, model.scale);
}

float verticalFovRadians(const Camera& camera, float aspect) {
    float fov = glm::radians(camera.fovyDeg);
    if (!(aspect < 1.0f) || !(aspect > 0.0f)) {
        return fov; // wider than tall (or square): fovy_deg is the vertical field of view
    }
    // Taller than wide: fovy_deg spans the width, tan(vertical / 2) = tan(fovy / 2) / aspect.
    return 2.0f * std::atan(std::tan(fov * 0.5f) / aspect);
}

glm::mat4 projectionMatrix(const Camera& camera, float aspect) {
    return glm::perspective(verticalFovRadians(camera, aspect), aspect, camera.near, camera.far);
}

Transforms computeTransforms(const Preset& preset, float aspect) {
    Transforms t;
    t.model = modelMatrix(preset.model);
    t.view = glm::lookAt(preset.camera.eye, preset.camera.target, preset.camera.up);
    t.projection = projectionMatrix(preset.camera, aspect);
    t.modelView = t.view * t.model;
    glm::mat3 mv(t.modelView);
    // The correct normal matrix is the inverse-transpose; the model-view matrix itself is the
    // classic mistake, visible as soon as the scale is not uniform. Both are renormalized in
    // the shader.
    t.normalMatrix = preset.normalMatrix == NormalMatrixMode::InverseTranspose ? glm::transpose(glm::inverse(mv)) : mv;
    return t;
}

} // namespace lab
