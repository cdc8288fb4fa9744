// image_texture.cpp — glTexImage2D of an RGB image, rows as they are (top row first): ImGui's
// texture coordinates put v = 0 at the top, so no flip is needed.
#include "render/image_texture.h"

#include "render/gl.h"

#include <utility>

namespace lab {

namespace {

void deleteTexture(unsigned& id) {
    if (id != 0) {
        GLuint name = id;
        glDeleteTextures(1, &name);
    }
    id = 0;
}

} // namespace

ImageTexture::~ImageTexture() {
    deleteTexture(id_);
    deleteTexture(previous_);
}

void ImageTexture::retire() {
    deleteTexture(previous_);
    previous_ = std::exchange(id_, 0u);
    width_ = height_ = 0;
}

void ImageTexture::dropPrevious() { deleteTexture(previous_); }

bool ImageTexture::upload(const Image& image) {
    GLint most = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
    if (image.width <= 0 || image.height <= 0 || image.width > most || image.height > most) {
        retire(); // this frame may still show it
        return false;
    }
    GLuint id = 0;
    glGenTextures(1, &id); // before the old one goes: the new picture gets a new number
    glBindTexture(GL_TEXTURE_2D, id);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
    deleteTexture(previous_);
    previous_ = id_;
    id_ = id;
    width_ = image.width;
    height_ = image.height;
    return true;
}

} // namespace lab
