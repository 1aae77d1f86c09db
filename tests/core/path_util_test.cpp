// The shared path helpers (core/path_util.h): extensions as std::filesystem defines them, the
// directory of a file as POSIX dirname(3) does, and names resolved against a scene's directory.
#include "core/path_util.h"

#include <gtest/gtest.h>

namespace rayo {
namespace {

TEST(PathUtil, LowerExtensionOfTheLastComponent) {
    EXPECT_EQ(lower_extension("out.PNG"), ".png");
    EXPECT_EQ(lower_extension("renders/frame.Exr"), ".exr");
    EXPECT_EQ(lower_extension("archive.tar.gz"), ".gz");
    EXPECT_EQ(lower_extension("file."), ".");
    EXPECT_EQ(lower_extension("file"), "");
    EXPECT_EQ(lower_extension("dir.d/file"), "");  // a dot in a directory is not an extension
    EXPECT_EQ(lower_extension("dir.d/"), "");
    EXPECT_EQ(lower_extension(""), "");
    // A leading dot starts a hidden file's name (std::filesystem::path::extension).
    EXPECT_EQ(lower_extension(".json"), "");
    EXPECT_EQ(lower_extension("scenes/.json"), "");
    EXPECT_EQ(lower_extension("scenes/.backup.JSON"), ".json");
    EXPECT_EQ(lower_extension("."), "");
    EXPECT_EQ(lower_extension(".."), "");
}

TEST(PathUtil, ParentDirectoryIsDirname) {
    EXPECT_EQ(parent_directory("scene.json"), ".");  // the working directory, never ""
    EXPECT_EQ(parent_directory("./scene.json"), ".");
    EXPECT_EQ(parent_directory("/scene.json"), "/");
    EXPECT_EQ(parent_directory("scenes/scene.json"), "scenes");
    EXPECT_EQ(parent_directory("/work/scenes/scene.json"), "/work/scenes");
    EXPECT_EQ(parent_directory("a//b.obj"), "a");
    EXPECT_EQ(parent_directory("a/b/"), "a");  // the directory containing directory b
    EXPECT_EQ(parent_directory("//x"), "/");
    EXPECT_EQ(parent_directory("/"), "/");
    EXPECT_EQ(parent_directory(""), ".");
}

TEST(PathUtil, JoinPathResolvesAgainstADirectory) {
    EXPECT_EQ(join_path("scenes", "m.obj"), "scenes/m.obj");
    EXPECT_EQ(join_path("scenes/", "m.obj"), "scenes/m.obj");
    EXPECT_EQ(join_path("/", "m.obj"), "/m.obj");
    EXPECT_EQ(join_path(".", "m.obj"), "m.obj");
    EXPECT_EQ(join_path("", "meshes/m.obj"), "meshes/m.obj");
    EXPECT_EQ(join_path("scenes", "/abs/m.obj"), "/abs/m.obj");
    // A mesh named by a scene file resolves next to the scene, wherever the scene is.
    EXPECT_EQ(join_path(parent_directory("scenes/a.json"), "m.obj"), "scenes/m.obj");
    EXPECT_EQ(join_path(parent_directory("a.json"), "m.obj"), "m.obj");
    EXPECT_EQ(join_path(parent_directory("/a.json"), "m.obj"), "/m.obj");
}

}  // namespace
}  // namespace rayo
