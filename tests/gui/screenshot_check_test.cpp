// Checks the screenshot the GUI test takes (`sculptline --size 800x600 --screenshot ... --quit` under
// Xvfb, see CMakeLists.txt): what a person would see, not pixels of a reference image. The path
// comes from SCULPTLINE_SCREENSHOT.
#include <QColor>
#include <QImage>
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <set>
#include <string>

namespace {

/// Share of pixels that must differ from the background: the default scene fills much of the view.
constexpr double kMinForeground = 0.15;
/// Distinct colours of a lit, shaded scene number in the hundreds; a blank or flat picture has 1-3.
constexpr int kMinDistinctColours = 100;
/// Pixels of each kind of object that a person would notice at 800 x 600.
constexpr int kMinCurvePixels = 300;
constexpr double kMinSurfaceShare = 0.05;
constexpr int kMinGridPixels = 500;

QImage loadScreenshot()
{
    const char* path = std::getenv("SCULPTLINE_SCREENSHOT");
    if (!path) return {};
    return QImage(QString::fromLocal8Bit(path)).convertToFormat(QImage::Format_RGB32);
}

/// The most frequent colour: the background of a scene framed with margin.
QRgb dominantColour(const QImage& image)
{
    std::map<QRgb, int> counts;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) ++counts[image.pixel(x, y)];
    QRgb best = 0;
    int bestCount = -1;
    for (const auto& [colour, count] : counts) {
        if (count > bestCount) {
            best = colour;
            bestCount = count;
        }
    }
    return best;
}

/// Pixels in the rectangle matching `predicate`.
template <typename Predicate>
int countPixels(const QImage& image, const QRect& rect, Predicate predicate)
{
    int n = 0;
    for (int y = rect.top(); y <= rect.bottom(); ++y)
        for (int x = rect.left(); x <= rect.right(); ++x) n += predicate(QColor(image.pixel(x, y))) ? 1 : 0;
    return n;
}

class Screenshot : public testing::Test {
protected:
    void SetUp() override
    {
        image_ = loadScreenshot();
        ASSERT_FALSE(image_.isNull()) << "SCULPTLINE_SCREENSHOT unset or not a readable image";
    }
    QImage image_;
};

TEST_F(Screenshot, HasTheRequestedViewportSize)
{
    EXPECT_EQ(image_.width(), 800);
    EXPECT_EQ(image_.height(), 600);
}

/// A window opened without --size (as ./run.sh does) must leave the 3D viewport a usable size
/// beside the docks: the window's minimum for its central area less the viewer's wheels.
TEST(DefaultWindow, ViewportIsUsableWithoutSize)
{
    constexpr int kMinWidth = 400, kMinHeight = 340;
    const char* path = std::getenv("SCULPTLINE_DEFAULT_SCREENSHOT");
    if (!path) GTEST_SKIP() << "SCULPTLINE_DEFAULT_SCREENSHOT unset (run through ctest)";
    const QImage image(QString::fromLocal8Bit(path));
    ASSERT_FALSE(image.isNull()) << path;
    EXPECT_GE(image.width(), kMinWidth);
    EXPECT_GE(image.height(), kMinHeight);
}

TEST_F(Screenshot, IsNotBlank)
{
    const QRgb background = dominantColour(image_);
    const int total = image_.width() * image_.height();
    const int foreground = countPixels(image_, image_.rect(), [&](const QColor& c) { return c.rgb() != background; });
    EXPECT_GT(foreground, kMinForeground * total) << "background " << std::hex << background;
    // Not black either: the Xvfb failure mode of a GL grab is an all-black picture
    EXPECT_NE(qGray(background), 0);

    std::set<QRgb> colours;
    for (int y = 0; y < image_.height(); ++y)
        for (int x = 0; x < image_.width(); ++x) colours.insert(image_.pixel(x, y));
    EXPECT_GE(static_cast<int>(colours.size()), kMinDistinctColours);
}

TEST_F(Screenshot, ShowsTheCurveTheSurfaceAndTheGrid)
{
    // The default scene's colours (scene/default_scene.cpp, scene/ground_grid.cpp): an orange
    // curve, a blue shaded surface, grey grid lines on a dark background.
    const int total = image_.width() * image_.height();
    const int curve = countPixels(image_, image_.rect(), [](const QColor& c) {
        return c.red() > 200 && c.green() > 80 && c.green() < 170 && c.blue() < 80;
    });
    const int surface = countPixels(image_, image_.rect(), [](const QColor& c) {
        return c.blue() > c.red() + 30 && c.blue() > 60 && c.hue() > 190 && c.hue() < 230;
    });
    const int grid = countPixels(image_, image_.rect(), [](const QColor& c) {
        return c.saturation() < 60 && c.value() > 80 && c.value() < 200;
    });
    EXPECT_GE(curve, kMinCurvePixels);
    EXPECT_GE(surface, kMinSurfaceShare * total);
    EXPECT_GE(grid, kMinGridPixels);
}

TEST_F(Screenshot, CentreAndGroundAreNotASingleColour)
{
    // The middle of the view holds the geometry, the lower half the ground grid: neither may be flat
    const QRect centre(image_.width() / 4, image_.height() / 4, image_.width() / 2, image_.height() / 2);
    const QRect ground(0, image_.height() / 2, image_.width(), image_.height() / 2);
    for (const QRect& rect : {centre, ground}) {
        std::set<QRgb> colours;
        for (int y = rect.top(); y <= rect.bottom(); ++y)
            for (int x = rect.left(); x <= rect.right(); ++x) colours.insert(image_.pixel(x, y));
        EXPECT_GE(static_cast<int>(colours.size()), kMinDistinctColours / 2)
            << "region " << rect.x() << "," << rect.y() << " " << rect.width() << "x" << rect.height();
    }
}

}  // namespace
