// SPDX-License-Identifier: Apache-2.0
// The safe writer, the JSON bounds and the resource budget, tested as library calls (the CLI's
// side is in tests/cli/RegressionTest.cpp and tests/fault/fault-injection.sh).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "TempDir.h"
#include "core/JsonText.h"
#include "core/SafeWrite.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Limits.h"

using namespace flarekit;
using flarekit::test::TempDir;

namespace {

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

//! Restores the default limits when a test changed them.
struct LimitsGuard {
    ~LimitsGuard() { setResourceLimits({}); }
};
}  // namespace

TEST(SafeWrite, ReplacesARegularFileAndKeepsItsPermissions) {
    TempDir dir;
    const std::string path = dir.file("a.txt");
    std::ofstream(path) << "old";
    ::chmod(path.c_str(), 0640);
    ASSERT_TRUE(writeFileSafely(path, "new content").ok());
    EXPECT_EQ(readAll(path), "new content");
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    EXPECT_EQ(dir.entries(), 1u);  // no temporary file left
}

TEST(SafeWrite, WritesThroughASymlinkAndKeepsTheLink) {
    TempDir dir;
    std::ofstream(dir.file("target.txt")) << "old";
    std::filesystem::create_symlink("target.txt", dir.file("link.txt"));
    ASSERT_TRUE(writeFileSafely(dir.file("link.txt"), "through the link").ok());
    EXPECT_TRUE(std::filesystem::is_symlink(dir.file("link.txt")));
    EXPECT_EQ(readAll(dir.file("target.txt")), "through the link");
    // A dangling link: the file it names is created.
    std::filesystem::create_symlink("new.txt", dir.file("dangling.txt"));
    ASSERT_TRUE(writeFileSafely(dir.file("dangling.txt"), "created").ok());
    EXPECT_TRUE(std::filesystem::is_symlink(dir.file("dangling.txt")));
    EXPECT_EQ(readAll(dir.file("new.txt")), "created");
}

TEST(SafeWrite, WritesDevicesInPlaceAndReportsTheirErrors) {
    // The test's own full device (mknod, as root), so that a broken writer replaces it rather
    // than the system's /dev/full; /dev/full where mknod is not allowed.
    TempDir dir;
    std::string full = dir.file("full");
    if (::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) full = "/dev/full";
    auto r = writeFileSafely(full, "no room");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, full + ": cannot write: No space left on device");
    struct stat st {};
    ASSERT_EQ(::stat(full.c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    EXPECT_TRUE(writeFileSafely("/dev/null", "gone").ok());
}

TEST(SafeWrite, AMissingDirectoryIsMadeAndAFileInItsWayIsBadInputAndWritesNothing) {
    TempDir dir;
    ASSERT_TRUE(writeFileSafely(dir.file("no/such/dir/x.txt"), "x").ok());
    EXPECT_EQ(readAll(dir.file("no/such/dir/x.txt")), "x");
    std::filesystem::remove_all(dir.file("no"));
    ASSERT_TRUE(writeFileSafely(dir.file("plain"), "p").ok());
    auto r = writeFileSafely(dir.file("plain/dir/x.txt"), "x");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(r.error().message.find("'" + dir.file("plain") + "' is not a directory"),
              std::string::npos)
        << r.error().message;
    EXPECT_EQ(dir.entries(), 1u);
}

TEST(SafeWrite, WritersRacingToMakeTheSameFolderAllSucceed) {
    // The generator's parallel samples make their layout's folders as they write: a folder that
    // another thread makes between two checks must not read as "not a directory".
    TempDir dir;
    for (int round = 0; round < 200; ++round) {
        const std::string folder = dir.file("r" + std::to_string(round) + "/a/b/c");
        std::vector<Status> results(4, Ok{});
        std::vector<std::thread> writers;
        for (int t = 0; t < 4; ++t)
            writers.emplace_back([&, t] {
                results[t] = writeFileSafely(folder + "/" + std::to_string(t) + ".txt", "x");
            });
        for (auto& w : writers) w.join();
        for (const Status& s : results) ASSERT_TRUE(s.ok()) << s.error().message;
    }
}

TEST(SafeWrite, ImageFormatsWithoutAnInMemoryWriterAreRefusedUpFront) {
    TempDir dir;
    auto r = checkOutputPath(dir.file("x.pfm"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("unsupported output format '.pfm'"), std::string::npos);
    EXPECT_TRUE(checkOutputPath(dir.file("x.png")).ok());
}

TEST(JsonBounds, NestingIsBoundedAt64Levels) {
    auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
    EXPECT_TRUE(parseJsonText(nested(64), "j.json").ok());
    auto deep = parseJsonText(nested(65), "j.json");
    ASSERT_FALSE(deep.ok());
    EXPECT_NE(deep.error().message.find("expected JSON nested at most 64 levels deep"),
              std::string::npos);
}

TEST(JsonBounds, NumberOverflowNamesItsField) {
    auto r = parseJsonText(R"({"a": [1, 2, {"b": 1e999}]})", "j.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message, "j.json: a[2].b: expected a finite number, got 1e999");
    auto top = parseJsonText("-1e400", "j.json");
    ASSERT_FALSE(top.ok());
    EXPECT_EQ(top.error().message, "j.json: (top level): expected a finite number, got -1e400");
}

TEST(JsonBounds, ValueCountStopsTheParse) {
    JsonLimits limits;
    limits.maxValues = 100;
    limits.what = "a test";
    std::string array = "[0";
    for (int i = 0; i < 200; ++i) array += ",0";
    auto r = parseJsonText(array + "]", "j.json", limits);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("expected at most 100 JSON values (a test)"),
              std::string::npos)
        << r.error().message;
}

TEST(JsonBounds, ExcerptsAreShortWhateverTheValue) {
    nlohmann::json big = nlohmann::json::array();
    for (int i = 0; i < 100000; ++i) big.push_back(i);
    const std::string e = jsonExcerpt(big);
    EXPECT_LE(e.size(), 60u);
    EXPECT_EQ(e.substr(0, 10), "[0,1,2,3,4");
    EXPECT_EQ(e.substr(e.size() - 3), "...");
    EXPECT_EQ(jsonExcerpt(nlohmann::json::parse("[[0,0,0],[1,0,0]]")), "[[0,0,0],[1,0,0]]");
    EXPECT_EQ(excerpt(std::string(5000, 'k'), 60), std::string(57, 'k') + "...");
}

TEST(Budget, ByteSizesParseInBinaryUnits) {
    EXPECT_EQ(parseByteSize("4G"), std::uint64_t(4) << 30);
    EXPECT_EQ(parseByteSize("4GiB"), std::uint64_t(4) << 30);
    EXPECT_EQ(parseByteSize("512m"), std::uint64_t(512) << 20);
    EXPECT_EQ(parseByteSize("1.5G"), std::uint64_t(3) << 29);
    EXPECT_EQ(parseByteSize("65536"), 65536u);
    EXPECT_FALSE(parseByteSize("lots"));
    EXPECT_FALSE(parseByteSize("0"));
    EXPECT_FALSE(parseByteSize("-1G"));
    EXPECT_FALSE(parseByteSize("4X"));
}

TEST(Budget, AnImageOverTheBudgetIsRefusedFromItsHeader) {
    LimitsGuard guard;
    TempDir dir;
    Image image(400, 300);
    image.fill({0.5f, 0.5f, 0.5f, 1.f});
    ASSERT_TRUE(writeImage(dir.file("a.png"), image).ok());
    ResourceLimits limits;
    limits.maxMemoryBytes = 1 << 20;
    // 1 MiB: 120,000 pixels at 32 bytes (RGBA floats) + 3 (the 8-bit RGB decode) is 4 MiB
    setResourceLimits(limits);
    auto r = readImage(dir.file("a.png"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("needs an estimated 4.01 MiB (400x300), over the memory "
                                     "budget of 1 MiB"),
              std::string::npos)
        << r.error().message;
    setResourceLimits({});
    EXPECT_TRUE(readImage(dir.file("a.png")).ok());
}
