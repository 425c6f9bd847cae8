#pragma once
// Which files a scene may name (a mesh's "file"). A scene file given on the command line may
// name any file: the person chose it. A scene that arrives over HTTP, from the explorer's page,
// may name only files under a few folders: whoever wrote it is not the person at the keyboard,
// and a scene that could name /etc/passwd as a mesh would let the loader's error lines quote
// any file of the machine (book §0.11). Every file a scene names goes through resolve(), from
// Fields::file: the one place the rule is applied, before any file is opened.
#include <filesystem>
#include <string>
#include <vector>

namespace rt {

class FileAccess {
public:
    // Any file, relative to the scene file's folder unless absolute (the command line's).
    FileAccess() = default;
    // Only files under `folders`; `adding` says in refusals how to add one ("--allow DIR").
    // Each folder is taken where it leads (made canonical now), whether or not it exists.
    FileAccess(const std::vector<std::string>& folders, std::string adding);

    // The path to open for `name`, relative to `base_dir` unless absolute. Confined, that is
    // the path with every symbolic link and ".." resolved, and it must lie under one of the
    // folders, compared component by component ("/a/bc" is not under "/a/b"); otherwise
    // throws std::runtime_error with one line naming the rule, and nothing of the file: the
    // same line whether or not it exists.
    std::string resolve(const std::string& name, const std::string& base_dir) const;

    bool confined() const { return confined_; }
    const std::vector<std::filesystem::path>& folders() const { return folders_; }

private:
    bool confined_ = false;
    std::vector<std::filesystem::path> folders_;
    std::string adding_;
};

}  // namespace rt
