// frame_pacer.cpp — frames owed and the next wake-up.
#include "app/frame_pacer.h"

namespace lab {

void FramePacer::drawn(double now, float redrawIn, bool inputQueued) {
    if (owed_ > 0 && !inputQueued) {
        --owed_;
    }
    if (redrawIn == 0.0f && owed_ == 0) {
        owed_ = 1;
    }
    wakeAt_ = redrawIn > 0.0f ? now + redrawIn : -1.0;
}

double FramePacer::sleepFor(double now, bool inputQueued) const {
    if (inputQueued || owed_ > 0) {
        return 0.0;
    }
    if (wakeAt_ < 0.0) {
        return -1.0;
    }
    return wakeAt_ > now ? wakeAt_ - now : 0.0;
}

} // namespace lab
