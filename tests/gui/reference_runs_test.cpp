// Reads what the gui_reference_* runs of the real program wrote (tests/gui/reference_import.cmake):
// the default scene without a reference, with the box imported by --import-reference, the same after
// a replayed Ctrl+Z, and the saved document reopened. Given / When / Then on the pictures a person
// would see and on the saved documents.
#include <QColor>
#include <QImage>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <string>

namespace {

/// A channel difference below this is the same colour (the renderer's dithering and blending).
constexpr int kChannelTolerance = 12;
/// The 60 x 40 x 50 mm box covers well over this many of the 800 x 600 pixels in the default view.
constexpr int kMinBoxPixels = 3000;
/// Pixels that may differ between two pictures of the same scene.
constexpr int kSameScenePixels = 20;
/// A colour whose channels spread by at most this is grey (the translucent grey over the
/// background, the grid and the curves behind it).
constexpr int kGreySpread = 48;

std::string dir()
{
    const char* d = std::getenv("SCULPTLINE_REFERENCE_DIR");
    return d ? d : "";
}

QImage picture(const std::string& name)
{
    const QImage image(QString::fromStdString(dir() + "/" + name));
    EXPECT_FALSE(image.isNull()) << name;
    return image.convertToFormat(QImage::Format_RGB32);
}

nlohmann::json document(const std::string& name)
{
    std::ifstream in(dir() + "/" + name);
    EXPECT_TRUE(in.good()) << name;
    return nlohmann::json::parse(in, nullptr, false);
}

struct Difference {
    int pixels = 0;
    int grey = 0;  ///< of those, grey in the second picture
};

Difference compare(const QImage& a, const QImage& b)
{
    Difference d;
    if (a.size() != b.size()) {
        ADD_FAILURE() << "sizes differ";
        return d;
    }
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            if (std::max({std::abs(p.red() - q.red()), std::abs(p.green() - q.green()), std::abs(p.blue() - q.blue())}) <= kChannelTolerance)
                continue;
            ++d.pixels;
            const int spread = std::max({q.red(), q.green(), q.blue()}) - std::min({q.red(), q.green(), q.blue()});
            if (spread <= kGreySpread) ++d.grey;
        }
    }
    return d;
}

TEST(ReferenceRuns, GivenTheBoxImportedByTheFlag_ThenItIsDrawnGreyOverTheScene)
{
    const Difference d = compare(picture("none.png"), picture("with.png"));
    EXPECT_GT(d.pixels, kMinBoxPixels);
    EXPECT_GT(d.grey, d.pixels * 3 / 4) << d.grey << " of " << d.pixels << " changed pixels are grey";
}

TEST(ReferenceRuns, GivenAReplayedCtrlZ_ThenTheReferenceIsGoneFromPictureAndDocument)
{
    const Difference d = compare(picture("none.png"), picture("undone.png"));
    EXPECT_LE(d.pixels, kSameScenePixels);
    const nlohmann::json undone = document("undone.json");
    EXPECT_FALSE(undone.contains("references")) << undone.dump().substr(0, 200);
}

TEST(ReferenceRuns, GivenTheSavedDocument_ThenItNamesTheFileAbsoluteAndRelative)
{
    const nlohmann::json with = document("orig/with.json");
    ASSERT_TRUE(with.contains("references"));
    ASSERT_EQ(with["references"].size(), 1u);
    EXPECT_EQ(with["references"][0]["path"], dir() + "/orig/box.iv");
    EXPECT_EQ(with["references"][0]["relative"], "box.iv");
}

TEST(ReferenceRuns, GivenTheSavedDocumentReopened_ThenTheReferenceIsBackAndSavedAgain)
{
    const Difference d = compare(picture("with.png"), picture("reopened.png"));
    EXPECT_LE(d.pixels, kSameScenePixels);
    const nlohmann::json reopened = document("reopened.json");
    ASSERT_TRUE(reopened.contains("references"));
    EXPECT_EQ(reopened["references"][0]["path"], dir() + "/orig/box.iv");
    EXPECT_EQ(reopened["references"][0]["relative"], "orig/box.iv");  // saved one folder up
}

}  // namespace
