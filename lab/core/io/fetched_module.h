// fetched_module.h — a part of the lab that the page leaves out of its first load and fetches, as a
// WebAssembly module of its own, the first time something needs it: the Draco decoder
// (core/gltf/draco_decoder.h) and the QR encoder (core/share/qr_encoder.h). The desktop and the
// command line link them: there they are always Ready.
#pragma once

#include <string>

namespace lab {

enum class ModuleState {
    Ready,     // works now
    NotLoaded, // the page has not fetched it yet
    Loading,   // the page is fetching it
    Failed,    // the page could not load it, or it stopped: problem() says why (the next use tries again)
};

#ifdef __EMSCRIPTEN__
// One such module in the page (fetched_module.cpp): `script` (say "qr.js") defines the module's
// factory `factory` (Emscripten's MODULARIZE, "LabQr"), whose module the page keeps as
// Module[`slot`] ("labQr") for the calls into it; the lab hears the outcome through its exported
// function `callback` (ok, why), which calls loaded().
class FetchedModule {
public:
    FetchedModule(const char* script, const char* factory, const char* slot, const char* callback)
        : script_(script), factory_(factory), slot_(slot), callback_(callback) {}

    ModuleState state() const { return state_; }
    const std::string& problem() const { return problem_; }
    void load(); // starts fetching it when it is NotLoaded or Failed; nothing otherwise
    void loaded(bool ok, const std::string& why);
    void failed(std::string why); // a call into it failed: it is dropped, and fetched again next time

private:
    const char* script_;
    const char* factory_;
    const char* slot_;
    const char* callback_;
    ModuleState state_ = ModuleState::NotLoaded;
    std::string problem_;
};
#endif

} // namespace lab
