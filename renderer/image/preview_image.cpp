#include "renderer/image/preview_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "renderer/image/colour_tables.h"
#include "renderer/image/image_file.h"
#include "skin/core/atomic_file.h"

namespace hylios {
namespace {

/// The font to hand to render_text: a DejaVu Sans file when one is installed (Debian:
/// fonts-dejavu-core), else "" (OpenImageIO's own search for a default font).
std::string fontName() {
  static const std::string name = [] {
    const char* candidates[] = {
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/dejavu/DejaVuSans.ttf", "/usr/local/share/fonts/DejaVuSans.ttf"};
    for (const char* path : candidates) {
      std::error_code error;
      if (std::filesystem::is_regular_file(path, error)) return std::string(path);
    }
    return std::string();
  }();
  return name;
}

}  // namespace

bool textRenderingAvailable() {
  static const bool available = [] {
    RgbCanvas probe = makeCanvas(64, 32);
    const bool drawn =
        drawImageText(probe.rgb.data(), probe.width, probe.height, 2, 24, "0.5", 16, fontName(), 0);
    if (!drawn) return false;
    // Some builds return success without FreeType; require that pixels actually changed.
    return std::any_of(probe.rgb.begin(), probe.rgb.end(), [](float v) { return v > 0.0f; });
  }();
  return available;
}

std::string asciiText(const std::string& text) {
  static const std::pair<const char*, const char*> kReplacements[] = {
      {"\u2212", "-"}, {"\u2013", "-"},      {"\u2014", "-"}, {"\u00b7", "|"},
      {"\u00b2", "2"}, {"\u00b3", "3"},      {"\u00b5", "u"}, {"\u00b1", "+/-"},
      {"\u00d7", "x"}, {"\u03bb", "lambda"}, {"\u2192", "->"}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (static_cast<unsigned char>(text[i]) < 0x80) {
      out += text[i++];
      continue;
    }
    bool replaced = false;
    for (const auto& [from, to] : kReplacements) {
      const std::size_t n = std::char_traits<char>::length(from);
      if (text.compare(i, n, from) == 0) {
        out += to;
        i += n;
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    out += '?';  // one '?' per unknown character: skip its continuation bytes
    ++i;
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  }
  return out;
}

int fittingFontSize(const std::string& text, int widthPx, int fontSizePx, int minimumPx) {
  if (!textRenderingAvailable() || text.empty()) return fontSizePx;
  const std::string ascii = asciiText(text);
  int size = fontSizePx;
  while (size > minimumPx && imageTextWidth(ascii, size, fontName()) > widthPx) --size;
  return size;
}

bool drawText(RgbCanvas& canvas, int x, int baselineY, const std::string& utf8Text, int fontSizePx,
              TextAnchor anchor) {
  if (utf8Text.empty()) return true;
  if (!textRenderingAvailable()) return false;
  const int alignX = anchor == TextAnchor::Left ? 0 : anchor == TextAnchor::Right ? 2 : 1;
  return drawImageText(canvas.rgb.data(), canvas.width, canvas.height, x, baselineY,
                       asciiText(utf8Text), fontSizePx, fontName(), alignX);
}

RgbCanvas makeCanvas(int width, int height) { return RgbCanvas(width, height); }

int colourBarStripHeight(int canvasWidth) {
  const int fontSize = std::clamp(canvasWidth / 20, 12, 24);
  const int gap = fontSize / 2, barHeight = fontSize, tickLength = fontSize / 3;
  return gap + barHeight + tickLength + fontSize + fontSize / 2;
}

PseudoColourPanel pseudoColourPanel(const std::vector<double>& values, int width, int height,
                                    double minValue, double maxValue, const std::string& caption) {
  if (values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("pseudoColourPanel: " + std::to_string(values.size()) +
                                " values for a " + std::to_string(width) + "x" +
                                std::to_string(height) + " image");
  }
  if (!(maxValue > minValue) || !std::isfinite(minValue) || !std::isfinite(maxValue)) {
    throw std::invalid_argument("pseudo-colour range [" + std::to_string(minValue) + ", " +
                                std::to_string(maxValue) + "] must be finite and increasing");
  }
  const int canvasWidth = std::max(width, kMinPseudoColourWidth);
  const int fontSize = std::clamp(canvasWidth / 20, 12, 24);
  const int gap = fontSize / 2, barHeight = fontSize, tickLength = fontSize / 3;
  PseudoColourPanel panel;
  panel.image = makeCanvas(canvasWidth, height + colourBarStripHeight(canvasWidth));
  const int offsetX = (canvasWidth - width) / 2;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double v = values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)];
      panel.image.set(offsetX + x, y, colourMap((v - minValue) / (maxValue - minValue)));
    }
  }
  // The bar: colour map from min (left) to max (right), with ticks at both ends and the middle.
  const int margin = std::max(fontSize / 2, 4);
  const int barLeft = margin, barRight = canvasWidth - margin - 1, barTop = height + gap;
  for (int x = barLeft; x <= barRight; ++x) {
    const auto rgb = colourMap(static_cast<double>(x - barLeft) / (barRight - barLeft));
    for (int y = barTop; y < barTop + barHeight; ++y) panel.image.set(x, y, rgb);
  }
  const int ticks[3] = {barLeft, (barLeft + barRight) / 2, barRight};
  for (const int x : ticks) {
    for (int y = barTop + barHeight; y < barTop + barHeight + tickLength; ++y)
      panel.image.set(x, y, {1.0, 1.0, 1.0});
  }
  const int baseline = barTop + barHeight + tickLength + fontSize;
  panel.labelled = drawText(panel.image, barLeft, baseline, formatLabelNumber(minValue), fontSize,
                            TextAnchor::Left) &&
                   drawText(panel.image, barRight + 1, baseline, formatLabelNumber(maxValue),
                            fontSize, TextAnchor::Right) &&
                   drawText(panel.image, (barLeft + barRight) / 2, baseline, caption, fontSize,
                            TextAnchor::Centre);
  return panel;
}

void writePngAtomically(const RgbCanvas& image, const std::filesystem::path& path) {
  std::vector<unsigned char> bytes(image.rgb.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const float v = image.rgb[i];
    if (std::isnan(v)) throw std::runtime_error("NaN in preview image '" + path.string() + "'");
    bytes[i] = static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  }
  static const std::vector<std::string> kChannels{"R", "G", "B"};
  ImageToWrite pixels;
  pixels.width = image.width;
  pixels.height = image.height;
  pixels.channelNames = &kChannels;
  pixels.bytes = bytes.data();
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    writeImageFile(tmp, ImageFileFormat::Png8, pixels, {}, path);
  });
}

std::string formatLabelNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace hylios
