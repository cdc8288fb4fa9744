// site_files.h — the files the page's site holds beside its first load: the bundled models
// (presets/models), which only a few presets name. One implementation compiled: local
// (site_files_local.cpp: the desktop, the command line, the tests — every file is on disk) or
// fetched (site_files_fetched.cpp: the page leaves them out of lab.data and fetches one the first
// time a preset, a link or the model field needs it; lab/app/workspace.cpp waits for it).
#pragma once

#include <filesystem>
#include <string>

namespace lab {

enum class SiteFile {
    Here,     // in the file system (or not one of the site's: the loader says whether it exists)
    Missing,  // one of the site's, not fetched yet: fetchSiteFile
    Fetching, // the page is fetching it
    Failed,   // the page could not fetch it: told once (`why`), then Missing again
};

// Where `file` (a canonical path) stands. A failure is reported to one caller only: the next
// asks again (Missing), as a new try fetches it again.
SiteFile siteFile(const std::filesystem::path& file, std::string* why = nullptr);

// Whether `file` is one of the site's, fetched or not: a preset may name it while it is not here.
bool onSite(const std::filesystem::path& file);

// Starts fetching `file` when it is Missing or Failed; nothing otherwise.
void fetchSiteFile(const std::filesystem::path& file);

// Whether any fetch is under way (the page's lab_settled waits for them).
bool siteFilesFetching();

#ifdef __EMSCRIPTEN__
// The page's answer to fetchSiteFile (lab_site_file_fetched, lab/platform/web_window.cpp): the
// file was written into the file system (ok), or why not.
void siteFileFetched(const std::filesystem::path& file, bool ok, const std::string& why);
#endif

} // namespace lab
