// image_texture.h — a CPU image (core/io/image.h) as a GL texture, for the UI to show with
// ImGui::Image: the sweep view's grid. The UI gets only the texture's number (id()), never GL.
//
// Owns one texture object; upload() replaces it with a new one, so a new picture always has a
// new number while the old one is still alive, and ImGui's draw data (which the window compares
// frame to frame to skip unchanged frames, platform/imgui_host.cpp) differs whenever the picture
// does. The old one lives on until dropPrevious(): the frame that uploads has already handed
// its number to ImGui. For the same reason a texture given up is retired, not deleted: it too
// lives until the next dropPrevious(). It does not draw.
#pragma once

#include "core/io/image.h"

namespace lab {

class ImageTexture {
public:
    ImageTexture() = default;
    ~ImageTexture();
    ImageTexture(const ImageTexture&) = delete;
    ImageTexture& operator=(const ImageTexture&) = delete;

    // Uploads `image` (RGB, top row first) into a new texture, filtered linearly; false when the
    // GL refuses it (too large), and then holds none (the current one retired).
    bool upload(const Image& image);
    void retire();       // holds none; the current one is deleted by the next dropPrevious()
    void dropPrevious(); // deletes the one the last upload replaced or retire() gave up
    unsigned id() const { return id_; } // 0: none
    int width() const { return width_; }
    int height() const { return height_; }

private:
    unsigned id_ = 0, previous_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace lab
