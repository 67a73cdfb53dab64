// Building blocks of the PNG previews: an RGB float canvas (renderer/image/rgb_canvas.h), text
// labels (FreeType through OpenImageIO's render_text, with a DejaVu/system font, in the image-file
// module: renderer/image/image_file.h), a pseudo-colour panel with its colour bar, and atomic PNG
// writing.
//
// Text needs a FreeType-enabled OpenImageIO and a font; textRenderingAvailable() says whether this
// machine has both. Without them labels are skipped and callers put the numbers in a sidecar file.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/image/rgb_canvas.h"

namespace hylios {

/// True when drawText() can render (probed once: a font is found and OpenImageIO draws with it).
bool textRenderingAvailable();

enum class TextAnchor { Left, Centre, Right };
/// Draws white `text` with its baseline at y, anchored at x. Returns false (drawing nothing) when
/// text rendering is unavailable. OpenImageIO's text drawing takes bytes, not UTF-8, so the few
/// non-ASCII characters captions use are drawn as ASCII first (asciiText).
bool drawText(RgbCanvas& canvas, int x, int baselineY, const std::string& text, int fontSizePx,
              TextAnchor anchor);
/// `text` with − – — → "-", · → "|", ² → "2", ³ → "3", µ → "u", ± → "+/-", × → "x", λ → "lambda",
/// → → "->" and any other non-ASCII byte → "?".
std::string asciiText(const std::string& text);
/// The largest font size up to `fontSizePx` (at least `minimumPx`) at which `text` is at most
/// `widthPx` wide; `fontSizePx` when text rendering is unavailable.
int fittingFontSize(const std::string& text, int widthPx, int fontSizePx, int minimumPx = 9);

/// A black canvas (throws std::invalid_argument unless both sizes are positive).
RgbCanvas makeCanvas(int width, int height);

/// A preview of one scalar image (row-major, width × height) through the colour map over the fixed
/// range [minValue, maxValue], with a colour bar strip beneath it: tick marks at both ends and the
/// middle, and the numbers (and `caption` centred) as text when available. The canvas is at least
/// kMinPseudoColourWidth wide so that the bar stays readable for tiny films.
struct PseudoColourPanel {
  RgbCanvas image;
  bool labelled = false;  ///< the min/max numbers were drawn as text
};
inline constexpr int kMinPseudoColourWidth = 200;
PseudoColourPanel pseudoColourPanel(const std::vector<double>& values, int width, int height,
                                    double minValue, double maxValue, const std::string& caption);
/// Height of the strip pseudoColourPanel() adds under an image of the given canvas width.
int colourBarStripHeight(int canvasWidth);

/// Writes an 8-bit RGB PNG (values in [0, 1] display space, clamped; a NaN is an error) via
/// writeAtomically.
void writePngAtomically(const RgbCanvas& image, const std::filesystem::path& path);

/// "%.4g"-style number for labels.
std::string formatLabelNumber(double value);

}  // namespace hylios
