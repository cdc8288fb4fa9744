// fetched_module.cpp — the page's modules fetched on demand (fetched_module.h).
#include "core/io/fetched_module.h"

#include "core/io/safe_text.h"

#include <emscripten.h>

namespace lab {

namespace {

// clang-format off
// Loads `script` (a <script> element), makes its module with the factory it defines and keeps it
// as Module[slot]; tells the lab with Module's `callback`(ok, why).
EM_JS(void, labJsLoadModule, (const char* script, const char* factory, const char* slot, const char* callback), {
    const file = UTF8ToString(script), name = UTF8ToString(factory), key = UTF8ToString(slot);
    const answer = UTF8ToString(callback);
    const done = (ok, why) => Module.ccall(answer, null, ["number", "string"], [ok, why]);
    const element = document.createElement("script");
    element.src = file;
    element.onload = () => {
        const make = window[name];
        if (typeof make !== "function") { done(0, file + " defines no " + name); return; }
        // Emscripten rejects with "Aborted(why). Build with -s ASSERTIONS=1 for more info.": the why,
        // whole, though it has parentheses of its own ("CompileError: WebAssembly.instantiate(): …").
        // (No regular expression: EM_JS's text is a C string, where a backslash starts an escape.)
        const reason = (e) => {
            const text = String((e && e.message) || e), from = text.indexOf("Aborted(");
            if (from < 0) return text;
            const build = text.indexOf(". Build with", from), why = text.substring(from + 8, build < 0 ? text.length : build);
            return why.endsWith(")") ? why.slice(0, -1) : why;
        };
        make().then((m) => { Module[key] = m; done(1, ""); },
                    (e) => done(0, file.slice(0, -3) + ".wasm could not be loaded: " + reason(e)));
    };
    element.onerror = () => done(0, file + " could not be fetched");
    document.head.appendChild(element);
});
EM_JS(void, labJsDropModule, (const char* slot), { Module[UTF8ToString(slot)] = null; });
// clang-format on

} // namespace

void FetchedModule::load() {
    if (state_ == ModuleState::NotLoaded || state_ == ModuleState::Failed) {
        state_ = ModuleState::Loading;
        labJsLoadModule(script_, factory_, slot_, callback_);
    }
}

void FetchedModule::loaded(bool ok, const std::string& why) {
    state_ = ok ? ModuleState::Ready : ModuleState::Failed;
    problem_ = ok ? "" : shortened(why); // the browser's and Emscripten's words: cut as other libraries' are
}

void FetchedModule::failed(std::string why) {
    labJsDropModule(slot_);
    state_ = ModuleState::Failed;
    problem_ = std::move(why);
}

} // namespace lab
