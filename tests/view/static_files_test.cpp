// resolve_static: only regular files inside a mount, however the path is spelled.
#include <gtest/gtest.h>

#include <fstream>

#include "../mesh/mesh_fixtures.hpp"
#include "view/static_files.hpp"

namespace isopatch::view {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

TEST(StaticFiles, SafePaths) {
  EXPECT_TRUE(is_safe_url_path("/"));
  EXPECT_TRUE(is_safe_url_path("/main.js"));
  EXPECT_TRUE(is_safe_url_path("/three/build/three.module.js"));
  EXPECT_TRUE(is_safe_url_path("/a/b/"));
  for (const char* bad : {"", "main.js", "/../x", "/a/../../x", "/a/./b", "/.", "/a/..", "//etc/passwd",
                          "/a//b", "/a\\..\\b", "/a\nb", "/a\x7f"})
    EXPECT_FALSE(is_safe_url_path(bad)) << bad;
  EXPECT_FALSE(is_safe_url_path(std::string("/a\0b", 4)));
  EXPECT_FALSE(is_safe_url_path("/" + std::string(2000, 'a')));
}

TEST(StaticFiles, ResolvesInsideMountsOnly) {
  const test::TempDir dir;
  const fs::path page = dir.path() / "page";
  const fs::path lib = dir.path() / "lib";
  write(page / "index.html", "<html>");
  write(page / "js" / "main.js", "main");
  write(lib / "three.js", "three");
  write(dir.path() / "secret.txt", "secret");
  fs::create_symlink(dir.path() / "secret.txt", page / "link.txt");  // a link out of the mount
  const std::vector<Mount> mounts = {{"/", page}, {"/lib/", lib}};

  EXPECT_EQ(resolve_static(mounts, "/"), fs::canonical(page / "index.html"));
  EXPECT_EQ(resolve_static(mounts, "/js/main.js"), fs::canonical(page / "js" / "main.js"));
  EXPECT_EQ(resolve_static(mounts, "/lib/three.js"), fs::canonical(lib / "three.js"));
  EXPECT_FALSE(resolve_static(mounts, "/js"));   // a folder
  EXPECT_FALSE(resolve_static(mounts, "/js/"));  // a folder without index.html
  EXPECT_FALSE(resolve_static(mounts, "/missing.js"));
  EXPECT_FALSE(resolve_static(mounts, "/../secret.txt"));
  EXPECT_FALSE(resolve_static(mounts, "/lib/../secret.txt"));
  EXPECT_FALSE(resolve_static(mounts, "/link.txt"));
  EXPECT_FALSE(resolve_static(mounts, "/lib/../page/index.html"));
  EXPECT_FALSE(resolve_static({{"/lib/", lib}}, "/index.html")) << "no mount matches";
}

TEST(StaticFiles, ContentTypes) {
  EXPECT_EQ(content_type_for("a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(content_type_for("three.module.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type_for("style.css"), "text/css; charset=utf-8");
  EXPECT_EQ(content_type_for("blob"), "application/octet-stream");
}

}  // namespace
}  // namespace isopatch::view
