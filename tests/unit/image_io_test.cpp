// PNG output: round trip and atomic writing.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/png_writer.h"

namespace f2 {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir() {
    fs::path dir = fs::temp_directory_path() /
                   ("f2_image_io_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::create_directories(dir);
    return dir;
}

TEST(ImageIo, PngRoundTripKeepsEveryPixel) {
    Image image;
    image.resize(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x)
            image.at(x, y) = {std::uint8_t(x * 30), std::uint8_t(y * 50), std::uint8_t(x ^ y)};
    fs::path path = scratchDir() / "round.png";
    std::string error;
    ASSERT_TRUE(writePng(image, path.string(), error)) << error;
    Image back;
    ASSERT_TRUE(readPng(path.string(), back, error)) << error;
    EXPECT_TRUE(back == image);
}

TEST(ImageIo, FailedWriteLeavesNoFileAndSaysWhy) {
    Image image;
    image.resize(2, 2);
    fs::path path = scratchDir() / "no_such_dir" / "x.png";
    std::string error;
    EXPECT_FALSE(writePng(image, path.string(), error));
    EXPECT_NE(error.find("no_such_dir"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(path));
}

TEST(ImageIo, WriteReplacesAnExistingFileAndLeavesNoTemporary) {
    fs::path dir = scratchDir() / "replace";
    fs::create_directories(dir);
    Image a, b;
    a.resize(3, 3);
    b.resize(4, 2);
    b.at(3, 1) = {1, 2, 3};
    std::string error;
    ASSERT_TRUE(writePng(a, (dir / "f.png").string(), error));
    ASSERT_TRUE(writePng(b, (dir / "f.png").string(), error));
    Image back;
    ASSERT_TRUE(readPng((dir / "f.png").string(), back, error));
    EXPECT_TRUE(back == b);
    int files = 0;
    for (auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
    EXPECT_EQ(files, 1);  // no .tmp left over
}

}  // namespace
}  // namespace f2
