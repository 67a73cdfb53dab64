#include "renderer/image/film_output.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "renderer/image/colour_tables.h"
#include "renderer/image/image_file.h"
#include "renderer/image/preview_image.h"
#include "skin/core/atomic_file.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

/// Everything derived from the film before any file is written.
struct FilmImages {
  int width = 0, height = 0;
  std::vector<std::string> channelNames;  ///< spectral channels, then R, G, B
  std::vector<float> pixels;              ///< interleaved, channelNames.size() per pixel
  std::string rgbDescription;             ///< what R, G, B hold (written as an attribute)
};

/// Throws if any pixel's channel mean is NaN or infinite, naming the first such pixel.
void requireFiniteFilm(const Film& film) {
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      for (std::size_t c = 0; c < film.channels().size(); ++c) {
        const double v = film.value(x, y, c);
        if (!std::isfinite(v)) {
          std::ostringstream message;
          message << "film has a non-finite value (" << v << ") at pixel (" << x << ", " << y
                  << "), " << film.channels()[c].wavelengthNm << " nm, band '"
                  << film.desc().bands[film.channels()[c].band].name << "'; nothing written";
          throw std::runtime_error(message.str());
        }
      }
    }
  }
}

std::vector<std::size_t> channelsOfBand(const Film& film, std::size_t band) {
  std::vector<std::size_t> indices;
  for (std::size_t c = 0; c < film.channels().size(); ++c)
    if (film.channels()[c].band == band) indices.push_back(c);
  return indices;
}

/// Which samples a film value is taken from: all, or one half (the noise estimate).
enum class FilmHalf { All, First, Second };

double filmValue(const Film& film, int x, int y, std::size_t c, FilmHalf half) {
  return half == FilmHalf::All ? film.value(x, y, c)
                               : film.halfValue(x, y, c, half == FilmHalf::Second);
}

/// Linear sRGB of a colour band at a pixel: XYZ = k·Σ L(λ_i)·cmf(λ_i)·Δλ, then the sRGB matrix.
std::array<double, 3> pixelLinearSrgb(const Film& film, int x, int y,
                                      const std::vector<std::size_t>& channels, double stepNm,
                                      double normalisation, FilmHalf half = FilmHalf::All) {
  std::array<double, 3> xyz{0, 0, 0};
  for (const std::size_t c : channels) {
    const auto cmf = cie1931(film.channels()[c].wavelengthNm);
    const double radiance = filmValue(film, x, y, c, half);
    for (int i = 0; i < 3; ++i) xyz[i] += radiance * cmf[i] * stepNm;
  }
  for (double& v : xyz) v *= normalisation;
  return xyzToLinearSrgb(xyz);
}

/// The band's radiance at a pixel: the single channel's mean, or the mean over a range's channels.
double pixelBandMean(const Film& film, int x, int y, const std::vector<std::size_t>& channels,
                     FilmHalf half = FilmHalf::All) {
  double sum = 0;
  for (const std::size_t c : channels) sum += filmValue(film, x, y, c, half);
  return sum / static_cast<double>(channels.size());
}

/// "name=365" or "name=380:780:10" per band, joined by ';' (the EXR attribute hylios:bands).
std::string bandsAttribute(const std::vector<BandDesc>& bands) {
  std::ostringstream text;
  text.precision(17);
  for (std::size_t b = 0; b < bands.size(); ++b) {
    text << (b ? ";" : "") << bands[b].name << "=" << bands[b].minNm;
    if (bands[b].isRange()) text << ":" << bands[b].maxNm << ":" << bands[b].stepNm;
  }
  return text.str();
}

FilmImages buildImages(const Film& film) {
  FilmImages images;
  images.width = film.width();
  images.height = film.height();
  for (const auto& channel : film.channels())
    images.channelNames.push_back(spectralChannelName(channel.wavelengthNm));
  images.channelNames.insert(images.channelNames.end(), {"R", "G", "B"});
  const bool coverage = !film.coverage().empty();
  if (coverage)
    images.channelNames.push_back("A");  // 1 where the pixel's centre ray sees an object
  const auto& bands = film.desc().bands;
  std::size_t rgbBand = 0;
  bool colour = false;
  for (std::size_t b = 0; b < bands.size(); ++b) {
    if (isColourBand(bands[b])) {
      rgbBand = b;
      colour = true;
      break;
    }
  }
  const auto rgbChannels = channelsOfBand(film, rgbBand);
  const double exposure = film.desc().exposure;
  const double normalisation = colour ? colourBandNormalisation(bands[rgbBand]) : 0.0;
  images.rgbDescription =
      colour ? "linear sRGB (CIE 1931 2 deg, D65 white) of band '" + bands[rgbBand].name +
                   "', Y = 1 for radiance D65/100 (d65 emission of scale 1), times exposure " +
                   formatLabelNumber(exposure)
             : "grey: radiance of band '" + bands[rgbBand].name + "' (mean over its channels)";
  const std::size_t stride = images.channelNames.size();
  images.pixels.assign(stride * static_cast<std::size_t>(images.width) * images.height, 0.0f);
  for (int y = 0; y < images.height; ++y) {
    for (int x = 0; x < images.width; ++x) {
      float* pixel = &images.pixels[(static_cast<std::size_t>(y) * images.width + x) * stride];
      for (std::size_t c = 0; c < film.channels().size(); ++c)
        pixel[c] = static_cast<float>(film.value(x, y, c));
      std::array<double, 3> rgb{};
      if (colour) {
        rgb = pixelLinearSrgb(film, x, y, rgbChannels, bands[rgbBand].stepNm, normalisation);
        for (double& v : rgb) v *= exposure;
      } else {
        rgb.fill(pixelBandMean(film, x, y, rgbChannels));
      }
      if (coverage)
        pixel[film.channels().size() + 3] =
            film.coverage()[static_cast<std::size_t>(y) * static_cast<std::size_t>(images.width) +
                            x]
                ? 1.0f
                : 0.0f;
      for (int i = 0; i < 3; ++i) {
        pixel[film.channels().size() + static_cast<std::size_t>(i)] = static_cast<float>(rgb[i]);
        if (!std::isfinite(pixel[film.channels().size() + static_cast<std::size_t>(i)]))
          throw std::runtime_error("RGB preview overflows float at pixel (" + std::to_string(x) +
                                   ", " + std::to_string(y) + "); nothing written");
      }
      for (std::size_t c = 0; c < film.channels().size(); ++c) {
        if (!std::isfinite(pixel[c]))
          throw std::runtime_error("film value overflows float at pixel (" + std::to_string(x) +
                                   ", " + std::to_string(y) + "), channel " +
                                   images.channelNames[c] + "; nothing written");
      }
    }
  }
  return images;
}

void writeExr(const FilmImages& images, const Film& film,
              const std::vector<std::pair<std::string, std::string>>& extraAttributes,
              const fs::path& path) {
  std::vector<ImageAttribute> attributes{
      {"spectralLayoutVersion", std::string("1.0")},
      {"emissiveUnits", std::string("W.m^-2.sr^-1")},
      {"hylios:spp", film.samplesPerPixelDone()},
      {"hylios:sppTarget", film.desc().samplesPerPixel},
      {"hylios:exposure", static_cast<float>(film.desc().exposure)},
      {"hylios:rgb", images.rgbDescription},
      {"hylios:bands", bandsAttribute(film.desc().bands)}};
  for (const auto& [name, value] : extraAttributes) attributes.push_back({name, value});
  ImageToWrite pixels;
  pixels.width = images.width;
  pixels.height = images.height;
  pixels.channelNames = &images.channelNames;
  pixels.pixels = images.pixels.data();
  // The temporary name has no .exr extension: the format is named explicitly.
  writeAtomically(path, [&](const fs::path& tmp) {
    writeImageFile(tmp, ImageFileFormat::ExrFloat, pixels, attributes, path);
  });
}

/// A band name made safe for a file name: letters, digits, '-', '_' and '.' kept, others '_'.
std::string fileSafe(const std::string& name) {
  std::string safe = name.empty() ? std::string("band") : name;
  for (char& ch : safe) {
    const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '-' || ch == '_' || ch == '.';
    if (!keep) ch = '_';
  }
  return safe;
}

RgbCanvas colourPreview(const Film& film, std::size_t band) {
  const BandDesc& desc = film.desc().bands[band];
  const auto channels = channelsOfBand(film, band);
  const double normalisation = colourBandNormalisation(desc);
  RgbCanvas image = makeCanvas(film.width(), film.height());
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const auto rgb = pixelLinearSrgb(film, x, y, channels, desc.stepNm, normalisation);
      image.set(
          x, y,
          {srgbEncode(rgb[0] * film.desc().exposure), srgbEncode(rgb[1] * film.desc().exposure),
           srgbEncode(rgb[2] * film.desc().exposure)});
    }
  }
  return image;
}

/// A file's first three channels as RGB (fewer than three: the first channel as grey).
RgbCanvas asRgb(const StoredImage& stored) {
  RgbCanvas image = makeCanvas(stored.width, stored.height);
  const std::size_t channels = stored.channelNames.size();
  for (std::size_t p = 0; p * 3 < image.rgb.size(); ++p)
    for (std::size_t c = 0; c < 3; ++c) {
      image.rgb[p * 3 + c] = stored.pixels[p * channels + (channels < 3 ? 0 : c)];
    }
  return image;
}

/// Copies `image` into `sheet` with its top-left corner at (x, y) (pixels outside are dropped).
void paste(const RgbCanvas& image, int x, int y, RgbCanvas& sheet) {
  for (int row = 0; row < image.height; ++row)
    for (int column = 0; column < image.width; ++column) {
      const int tx = x + column, ty = y + row;
      if (tx < 0 || ty < 0 || tx >= sheet.width || ty >= sheet.height) continue;
      const float* from = image.pixel(column, row);
      std::copy(from, from + 3, sheet.pixel(tx, ty));
    }
}

std::string bandCaption(const BandDesc& band) {
  return band.isRange()
             ? formatLabelNumber(band.minNm) + "-" + formatLabelNumber(band.maxNm) + " nm"
             : formatLabelNumber(band.minNm) + " nm";
}

}  // namespace

std::string spectralChannelName(double wavelengthNm) {
  if (!(wavelengthNm > 0) || !std::isfinite(wavelengthNm)) {
    throw std::invalid_argument("spectral channel wavelength must be positive and finite, got " +
                                std::to_string(wavelengthNm));
  }
  char number[64];
  std::snprintf(number, sizeof number, "%.6f", wavelengthNm);
  std::string text = number;
  std::replace(text.begin(), text.end(), '.', ',');
  return "S0." + text + "nm";
}

std::optional<double> parseSpectralChannelName(const std::string& name) {
  const std::string prefix = "S0.", suffix = "nm";
  if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return std::nullopt;
  }
  std::string number = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (number.find('.') != std::string::npos) return std::nullopt;
  std::replace(number.begin(), number.end(), ',', '.');
  if (number.empty() || !(std::isdigit(static_cast<unsigned char>(number[0])))) return std::nullopt;
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(number, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != number.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool isColourBand(const BandDesc& band) {
  return band.isRange() && band.minNm <= 400.0 && band.maxNm >= 700.0;
}

double colourBandNormalisation(const BandDesc& band) {
  if (!band.isRange()) throw std::invalid_argument("band '" + band.name + "' is not a range band");
  double whiteY = 0;
  for (const double wavelength : band.channelWavelengths()) {
    const double yBar = cie1931(wavelength)[1];
    // D65 / 100: the scene's "d65" emission of scale 1 (renderer/scene/emission_spectrum.h).
    if (yBar > 0) whiteY += d65(wavelength) / 100.0 * yBar * band.stepNm;
  }
  if (!(whiteY > 0)) {
    throw std::invalid_argument("band '" + band.name + "' has no channel where the eye responds");
  }
  return 1.0 / whiteY;
}

NoiseImage filmHalfNoiseImage(const Film& film, bool secondHalf) {
  NoiseImage image;
  image.width = film.width();
  image.height = film.height();
  const auto& bands = film.desc().bands;
  std::vector<std::vector<std::size_t>> channels;
  for (std::size_t b = 0; b < bands.size(); ++b) {
    image.groups.push_back("band " + bands[b].name);
    channels.push_back(channelsOfBand(film, b));
  }
  std::size_t colourBand = bands.size();
  for (std::size_t b = 0; b < bands.size() && colourBand == bands.size(); ++b)
    if (isColourBand(bands[b])) colourBand = b;
  const bool colour = colourBand < bands.size();
  if (colour) {
    for (const char* name : {"R", "G", "B"}) image.groups.push_back(name);
    image.rgb = {static_cast<int>(bands.size()), static_cast<int>(bands.size()) + 1,
                 static_cast<int>(bands.size()) + 2};
  }
  const double normalisation = colour ? colourBandNormalisation(bands[colourBand]) : 0.0;
  const FilmHalf half = secondHalf ? FilmHalf::Second : FilmHalf::First;
  image.values.reserve(static_cast<std::size_t>(image.width) * image.height * image.groups.size());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      for (std::size_t b = 0; b < bands.size(); ++b)
        image.values.push_back(pixelBandMean(film, x, y, channels[b], half));
      if (colour)
        for (double v : pixelLinearSrgb(film, x, y, channels[colourBand], bands[colourBand].stepNm,
                                        normalisation, half))
          image.values.push_back(v);
    }
  return image;
}

std::vector<double> filmSecondHalfShare(const Film& film) {
  const auto& bands = film.desc().bands;
  std::size_t colourBand = bands.size();
  for (std::size_t b = 0; b < bands.size() && colourBand == bands.size(); ++b)
    if (isColourBand(bands[b])) colourBand = b;
  std::vector<std::vector<std::size_t>> channels;
  for (std::size_t b = 0; b < bands.size(); ++b) channels.push_back(channelsOfBand(film, b));
  const std::size_t groups = bands.size() + (colourBand < bands.size() ? 3 : 0);
  // Paths that carry a whole band give each of its channels the same counts: one channel says it.
  if (film.wholeBandSamples())
    for (auto& c : channels) c.resize(std::min<std::size_t>(c.size(), 1));
  std::vector<double> share, ofBand(bands.size());
  share.reserve(static_cast<std::size_t>(film.width()) * film.height() * groups);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      for (std::size_t b = 0; b < bands.size(); ++b) {
        double all = 0, second = 0;
        for (const std::size_t c : channels[b]) {
          all += film.sampleCount(x, y, c);
          second += film.secondHalfSampleCount(x, y, c);
        }
        ofBand[b] = all > 0 ? second / all : 0.0;
      }
      share.insert(share.end(), ofBand.begin(), ofBand.end());
      if (colourBand < bands.size()) share.insert(share.end(), 3, ofBand[colourBand]);
    }
  return share;
}

std::vector<GroupNoise> filmNoise(const Film& film) {
  return measureHalvesNoise(filmHalfNoiseImage(film, false), filmHalfNoiseImage(film, true),
                            filmSecondHalfShare(film), film.coverage());
}

std::vector<fs::path> writeFilmOutputs(
    const Film& film, const fs::path& exrPath,
    const std::vector<std::pair<std::string, std::string>>& extraAttributes) {
  requireFiniteFilm(film);
  const FilmImages images = buildImages(film);
  std::vector<fs::path> written;
  writeExr(images, film, extraAttributes, exrPath);
  written.push_back(exrPath);
  // An EXR "file" that is a device or FIFO (--out /dev/null) was written in place
  // (skin/core/atomic_file.h); previews beside it ("/dev/null_<band>.png") are files nobody asked
  // for, so there are none (issue 13, row 5).
  std::error_code error;
  const fs::file_status status = fs::status(exrPath, error);
  if (fs::exists(status) && !fs::is_regular_file(status)) return written;

  const std::string stem = exrPath.stem().string();
  const auto& bands = film.desc().bands;
  for (std::size_t b = 0; b < bands.size(); ++b) {
    const fs::path png = exrPath.parent_path() / (stem + "_" + fileSafe(bands[b].name) + ".png");
    if (isColourBand(bands[b])) {
      writePngAtomically(colourPreview(film, b), png);
      written.push_back(png);
      continue;
    }
    const auto channels = channelsOfBand(film, b);
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(film.width()) * film.height());
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x) values.push_back(pixelBandMean(film, x, y, channels));
    const auto panel =
        pseudoColourPanel(values, film.width(), film.height(), bands[b].previewMin,
                          bands[b].previewMax, "radiance at " + bandCaption(bands[b]));
    writePngAtomically(panel.image, png);
    written.push_back(png);
    if (!panel.labelled) {
      // No text rendering here: the colour bar's numbers go to a sidecar file instead.
      const fs::path sidecar =
          exrPath.parent_path() / (stem + "_" + fileSafe(bands[b].name) + "_scale.txt");
      writeTextAtomically(
          sidecar, "band " + bands[b].name + " (" + bandCaption(bands[b]) + "): colour bar from " +
                       formatLabelNumber(bands[b].previewMin) + " (left tick) to " +
                       formatLabelNumber(bands[b].previewMax) + " (right tick), middle tick " +
                       formatLabelNumber(0.5 * (bands[b].previewMin + bands[b].previewMax)) + "\n");
      written.push_back(sidecar);
    }
  }
  return written;
}

void writeContactSheet(const std::vector<fs::path>& panels, const std::vector<std::string>& labels,
                       const fs::path& out, int columns,
                       const std::vector<std::string>& titleLines) {
  if (panels.empty())
    throw std::invalid_argument("contact sheet '" + out.string() + "': no panels");
  if (labels.size() != panels.size()) {
    throw std::invalid_argument("contact sheet '" + out.string() +
                                "': " + std::to_string(panels.size()) + " panels but " +
                                std::to_string(labels.size()) + " labels");
  }
  if (columns <= 0)
    throw std::invalid_argument("contact sheet '" + out.string() + "': columns must be positive");
  std::vector<RgbCanvas> images;
  int cellWidth = 0, cellHeight = 0;
  for (const auto& path : panels) {
    StoredImage stored;
    std::string error;
    if (!tryReadImageFile(path, stored, error))
      throw std::runtime_error("contact sheet: cannot read panel '" + path.string() +
                               "': " + error);
    images.push_back(asRgb(stored));
    cellWidth = std::max(cellWidth, stored.width);
    cellHeight = std::max(cellHeight, stored.height);
  }
  const int fontSize = std::clamp(cellWidth / 16, 12, 28);
  const int labelHeight = fontSize * 2, padding = std::max(4, fontSize / 2);
  const int columnCount = std::min<int>(columns, static_cast<int>(panels.size()));
  const int rowCount = (static_cast<int>(panels.size()) + columnCount - 1) / columnCount;
  const int pitchX = cellWidth + padding, pitchY = cellHeight + labelHeight + padding;
  const int titleFont = std::max(12, fontSize * 3 / 4), titleLine = titleFont * 3 / 2;
  const int titleHeight = static_cast<int>(titleLines.size()) * titleLine;
  const int sheetWidth = padding + columnCount * pitchX;
  RgbCanvas sheet = makeCanvas(sheetWidth, padding + titleHeight + rowCount * pitchY);
  bool labelled = true;
  for (std::size_t t = 0; t < titleLines.size(); ++t)
    labelled =
        drawText(sheet, sheetWidth / 2, padding + static_cast<int>(t) * titleLine + titleFont,
                 titleLines[t], fittingFontSize(titleLines[t], sheetWidth - 2 * padding, titleFont),
                 TextAnchor::Centre) &&
        labelled;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const int column = static_cast<int>(i) % columnCount, row = static_cast<int>(i) / columnCount;
    const int left = padding + column * pitchX, top = padding + titleHeight + row * pitchY;
    paste(images[i], left + (cellWidth - images[i].width) / 2,
          top + (cellHeight - images[i].height) / 2, sheet);
    labelled =
        drawText(sheet, left + cellWidth / 2, top + cellHeight + fontSize + fontSize / 3, labels[i],
                 fittingFontSize(labels[i], cellWidth, fontSize), TextAnchor::Centre) &&
        labelled;
  }
  writePngAtomically(sheet, out);
  if (!labelled) {
    // No text rendering here: the labels go to a sidecar file, in reading order.
    std::string text;
    for (const std::string& line : titleLines) text += "title: " + line + "\n";
    for (std::size_t i = 0; i < labels.size(); ++i) {
      text += "row " + std::to_string(i / columnCount + 1) + ", column " +
              std::to_string(i % columnCount + 1) + ": " + labels[i] + "\n";
    }
    fs::path sidecar = out;
    sidecar.replace_extension(".labels.txt");
    writeTextAtomically(sidecar, text);
  }
}

}  // namespace hylios
