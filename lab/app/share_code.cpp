// share_code.cpp — the scene's link as a QR code (share_code.h).
#include "app/share_code.h"

#include "core/io/safe_text.h"
#include "core/share/qr_encoder.h"
#include "core/share/share_link.h"

namespace lab {

const ui::ShareCodeModel& ShareCode::update(const std::string& base, Workspace& workspace, bool editable) {
    model_.address = editable ? &address : nullptr;
    model_.addressProblem = addressProblem;
    const std::optional<ExerciseSession>& exercise = workspace.exercise();
    model_.title = exercise ? "Exercise: " + printable(exercise->exercise.title, true)
                            : printable(workspace.document().displayName(), true) +
                                  (workspace.document().dirty() ? " (modified)" : "");
    std::string url = base.empty() ? std::string{} : shareUrl(base, workspace.link());
    if (made_ && url == url_) {
        return model_;
    }
    made_ = true;
    url_ = url;
    code_.reset();
    model_.code = nullptr;
    model_.link = url;
    model_.problem.clear();
    model_.waiting = false;
    if (url.empty()) {
        model_.problem = editable ? "The QR code needs the course page's address: type it below (it is remembered), or "
                                    "start the lab once with\n  lab --share-base https://your-course.example.org/lab/"
                                  : "The QR code needs the course page's address. Start the lab once with\n"
                                    "  lab --share-base https://your-course.example.org/lab/\n"
                                    "(it is remembered), or use the page's Copy link.";
        return model_;
    }
    // The page fetches the QR encoder the first time it is needed (core/share/qr_encoder.h): the link
    // shows meanwhile, and the code is made in the frame after it arrived.
    if (qrEncoderState() != ModuleState::Ready) {
        if (qrEncoderState() == ModuleState::Failed && loadingFor_ == url) { // shown until the link changes
            model_.problem = "The QR encoder could not be loaded: " + qrEncoderProblem() +
                             ". The page's Copy link copies the scene's link instead; the next link tries again.";
            return model_;
        }
        if (qrEncoderState() != ModuleState::Loading) { // a new link tries again after a failure
            loadQrEncoder();
            loadingFor_ = url;
        }
        made_ = false; // asked again each frame until the encoder is here
        model_.problem = "Loading the QR encoder…";
        model_.waiting = true;
        return model_;
    }
    std::string error;
    code_ = encodeQr(url, error);
    if (code_) {
        model_.code = &*code_;
    } else {
        model_.problem = "This scene's link is too long for a QR code that can be read across a room: " + error +
                         ". Shorten the description or the exercise's text, or publish the exercise with the course "
                         "page and link it by name (lab share prints such links).";
    }
    return model_;
}

std::string ShareCode::newProblem() {
    const std::string why = model_.code || model_.waiting ? std::string() : printable(model_.problem);
    return why == std::exchange(said_, why) ? std::string() : why;
}

} // namespace lab
