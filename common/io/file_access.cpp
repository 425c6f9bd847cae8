#include "io/file_access.hpp"

#include "core/text.hpp"

#include <algorithm>
#include <stdexcept>
#include <system_error>

namespace rt {

namespace {

namespace fs = std::filesystem;

// Where `path` leads: absolute, every symbolic link and ".." of the part that exists resolved
// (as the kernel will when the file is opened), the rest normalised. Empty if it cannot be
// worked out (a loop of links, a folder that cannot be searched).
fs::path where(const fs::path& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    if (ec) return {};
    fs::path real = fs::weakly_canonical(absolute, ec);
    if (ec) return {};
    if (!real.has_filename()) real = real.parent_path();  // "dir/": the folder itself
    return real;
}

// Component by component: "/a/bc" is not under "/a/b", as a comparison of the strings would say.
bool under(const fs::path& path, const fs::path& folder) {
    return std::mismatch(folder.begin(), folder.end(), path.begin(), path.end()).first == folder.end();
}

}  // namespace

FileAccess::FileAccess(const std::vector<std::string>& folders, std::string adding)
    : confined_(true), adding_(std::move(adding)) {
    for (const std::string& f : folders)
        if (const fs::path real = where(f); !real.empty()) folders_.push_back(real);
}

std::string FileAccess::resolve(const std::string& name, const std::string& base_dir) const {
    fs::path path = name;
    if (path.is_relative()) path = fs::path(base_dir) / path;
    if (!confined_) return path.string();
    // A NUL ends the name the kernel sees: what was checked would not be what is opened.
    const fs::path real = name.find('\0') == std::string::npos ? where(path) : fs::path();
    if (!real.empty())
        for (const fs::path& folder : folders_)
            if (under(real, folder)) return real.string();
    const std::string list = or_list(folders_, [](const fs::path& f) { return f.string(); });
    throw std::runtime_error(one_line("'" + name + "' is refused: this scene may only name files under " +
                                      (list.empty() ? "no folder" : list) + " (" + adding_ + ")"));
}

}  // namespace rt
