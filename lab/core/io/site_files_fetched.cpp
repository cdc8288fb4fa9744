// site_files_fetched.cpp — the page's bundled models, fetched on demand (site_files.h).
//
// cmake/web.cmake leaves presets/models out of lab.data and copies it to the site's models/ folder;
// LAB_SITE_MODELS names its files ("a.glb|b.glb"). A file is fetched once, written beside the
// bundled presets (/presets/models, as the desktop has it) under a temporary name and renamed, so
// the loader never sees half a file; the platform then tells the lab (lab_site_file_fetched), and
// the open that waited for it is carried out again.
#include "core/io/site_files.h"

#include <emscripten.h>

#include <map>
#include <string_view>
#include <system_error>

namespace lab {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kNames = LAB_SITE_MODELS;
const fs::path kFolder = "/presets/models";

struct Fetch {
    SiteFile state = SiteFile::Missing;
    std::string why;
};
std::map<std::string, Fetch> gFetches; // by path: the site's files asked for so far

// Fetches `url` into `path` (written as path + ".part", then renamed); tells the lab with
// lab_site_file_fetched(path, ok, why).
// clang-format off
EM_JS(void, labJsFetchSiteFile, (const char* url, const char* path), {
    const file = UTF8ToString(path);
    const done = (ok, why) => Module.ccall("lab_site_file_fetched", null, ["string", "number", "string"], [file, ok, why]);
    fetch(UTF8ToString(url))
        .then((r) => {
            if (!r.ok) throw new Error("the server answered " + r.status + (r.statusText ? " " + r.statusText : ""));
            return r.arrayBuffer();
        })
        .then((bytes) => {
            FS.writeFile(file + ".part", new Uint8Array(bytes));
            FS.rename(file + ".part", file);
            done(1, "");
        })
        .catch((e) => done(0, String((e && e.message) || e)));
});
// clang-format on

} // namespace

bool onSite(const fs::path& file) {
    if (file.parent_path() != kFolder) {
        return false;
    }
    const std::string name = file.filename().string();
    for (std::string_view rest = kNames; !rest.empty();) {
        std::size_t bar = rest.find('|');
        if (rest.substr(0, bar) == name) {
            return true;
        }
        rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
    }
    return false;
}

SiteFile siteFile(const fs::path& file, std::string* why) {
    std::error_code ec;
    if (!onSite(file) || fs::is_regular_file(file, ec)) {
        return SiteFile::Here;
    }
    auto it = gFetches.find(file.string());
    if (it == gFetches.end()) {
        return SiteFile::Missing;
    }
    if (it->second.state == SiteFile::Failed) {
        if (why) {
            *why = it->second.why;
        }
        gFetches.erase(it); // told once: the next request fetches it again
        return SiteFile::Failed;
    }
    return it->second.state;
}

void fetchSiteFile(const fs::path& file) {
    SiteFile state = siteFile(file);
    if (state != SiteFile::Missing && state != SiteFile::Failed) {
        return;
    }
    std::error_code ec;
    fs::create_directories(kFolder, ec);
    gFetches[file.string()] = {SiteFile::Fetching, {}};
    const std::string url = "models/" + file.filename().string();
    labJsFetchSiteFile(url.c_str(), file.c_str());
}

bool siteFilesFetching() {
    for (const auto& [path, fetch] : gFetches) {
        if (fetch.state == SiteFile::Fetching) {
            return true;
        }
    }
    return false;
}

void siteFileFetched(const fs::path& file, bool ok, const std::string& why) {
    if (ok) {
        gFetches.erase(file.string());
    } else {
        gFetches[file.string()] = {SiteFile::Failed, why.empty() ? "it could not be fetched" : why};
    }
}

} // namespace lab
