// site_files_local.cpp — every file on disk (site_files.h): the desktop, the command line, the tests.
#include "core/io/site_files.h"

namespace lab {

SiteFile siteFile(const std::filesystem::path&, std::string*) {
    return SiteFile::Here;
}
bool onSite(const std::filesystem::path&) {
    return false;
}
void fetchSiteFile(const std::filesystem::path&) {}
bool siteFilesFetching() {
    return false;
}

} // namespace lab
