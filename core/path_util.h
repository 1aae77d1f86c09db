#pragma once
// Path-name helpers the loaders and image writers share: one definition each of a file's
// extension, its directory and a name resolved against a directory. Pure string functions of
// '/'-separated paths (POSIX, the platform rayo builds on); nothing is looked up on disk.
#include <string>

namespace rayo {

// The extension of the path's last component, with its dot, in lower case; "" when it has none.
// As std::filesystem::path::extension: "dir.d/file" has none, and neither does a name that only
// starts with a dot (".json", a hidden file) nor "." or "..".
std::string lower_extension(const std::string& path);

// The directory containing `path`, as POSIX dirname(3): "scene.json" -> "." (the working
// directory, not "": an empty directory would turn "dir/" + name into a path from the root),
// "/scene.json" -> "/", "a/b/scene.json" -> "a/b", trailing and repeated slashes ignored.
std::string parent_directory(const std::string& path);

// `name` resolved against the directory `dir`: `name` itself when it is absolute or when `dir`
// is "" or "." (so that files next to a scene in the working directory keep the name the scene
// gives them in messages), else dir + "/" + name with a single slash between them.
std::string join_path(const std::string& dir, const std::string& name);

}  // namespace rayo
