#include "renderer/image/image_comparison.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "renderer/image/film_output.h"
#include "renderer/image/image_file.h"

namespace hylios {
namespace {

/// Running sums over the compared values of one channel (or of the pooled channels).
struct DifferenceSums {
  std::size_t count = 0;
  double squaredDifference = 0, difference = 0, referenceAbs = 0;

  void add(double test, double reference) {
    ++count;
    squaredDifference += (test - reference) * (test - reference);
    difference += test - reference;
    referenceAbs += std::fabs(reference);
  }
  void add(const DifferenceSums& other) {
    count += other.count;
    squaredDifference += other.squaredDifference;
    difference += other.difference;
    referenceAbs += other.referenceAbs;
  }
};

ChannelDifference finish(const DifferenceSums& sums, const std::string& channel,
                         const std::string& referenceName) {
  ChannelDifference result;
  result.channel = channel;
  result.wavelengthNm = parseSpectralChannelName(channel);
  result.valuesCompared = sums.count;
  const double count = static_cast<double>(sums.count);
  result.rmse = std::sqrt(sums.squaredDifference / count);
  result.referenceMeanAbs = sums.referenceAbs / count;
  if (!(result.referenceMeanAbs > 0)) {
    throw std::invalid_argument("reference '" + referenceName + "': channel " + channel +
                                " is zero everywhere, so its relative error is undefined");
  }
  result.relativeRmse = result.rmse / result.referenceMeanAbs;
  result.meanRelativeDifference = (sums.difference / count) / result.referenceMeanAbs;
  return result;
}

std::string listChannels(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

/// For each of test's channels, its index in the reference; throws when the sets differ.
std::vector<std::size_t> matchChannels(const ExrImage& test, const std::string& testName,
                                       const ExrImage& reference,
                                       const std::string& referenceName) {
  std::vector<std::string> missingInReference, missingInTest;
  std::vector<std::size_t> match;
  for (const auto& name : test.channelNames) {
    std::size_t found = reference.channelNames.size();
    for (std::size_t r = 0; r < reference.channelNames.size(); ++r)
      if (reference.channelNames[r] == name) found = r;
    if (found == reference.channelNames.size()) missingInReference.push_back(name);
    match.push_back(found);
  }
  for (const auto& name : reference.channelNames) {
    bool found = false;
    for (const auto& other : test.channelNames) found = found || other == name;
    if (!found) missingInTest.push_back(name);
  }
  if (!missingInReference.empty() || !missingInTest.empty()) {
    std::string message = "images have different channels:";
    if (!missingInReference.empty())
      message += " '" + testName + "' has " + listChannels(missingInReference) + " which '" +
                 referenceName + "' lacks;";
    if (!missingInTest.empty())
      message += " '" + referenceName + "' has " + listChannels(missingInTest) + " which '" +
                 testName + "' lacks;";
    message.pop_back();
    throw std::invalid_argument(message);
  }
  return match;
}

/// The mean of channel c over the block whose top-left pixel is (x0, y0).
double blockMean(const ExrImage& image, int x0, int y0, int blockSize, std::size_t channel) {
  double sum = 0;
  for (int y = y0; y < y0 + blockSize; ++y)
    for (int x = x0; x < x0 + blockSize; ++x) sum += image.value(x, y, channel);
  return sum / (static_cast<double>(blockSize) * blockSize);
}

std::string formatNumber(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

/// A CSV field, quoted (RFC 4180) when it holds a comma or a quote — spectral channel names
/// ("S0.500,000000nm") do.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) {
    if (ch == '"') quoted += '"';
    quoted += ch;
  }
  return quoted + "\"";
}

}  // namespace

ExrImage readExrImage(const std::filesystem::path& path) {
  ExrImage image;
  static_cast<StoredImage&>(image) = readImageFile(path);
  const auto alpha = std::find(image.channelNames.begin(), image.channelNames.end(), "A");
  if (alpha != image.channelNames.end()) {  // the coverage mask: not a compared channel
    const std::size_t a = static_cast<std::size_t>(alpha - image.channelNames.begin());
    const std::size_t stride = image.channelNames.size();
    std::vector<float> kept;
    kept.reserve(image.pixels.size() / stride * (stride - 1));
    for (std::size_t p = 0; p * stride < image.pixels.size(); ++p) {
      image.coverage.push_back(image.pixels[p * stride + a] >= 0.5f);
      for (std::size_t c = 0; c < stride; ++c)
        if (c != a) kept.push_back(image.pixels[p * stride + c]);
    }
    image.pixels = std::move(kept);
    image.channelNames.erase(alpha);
  }
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!std::isfinite(image.pixels[i])) {
      const std::size_t pixel = i / image.channelNames.size();
      throw std::runtime_error("image '" + path.string() + "' has a non-finite value at pixel (" +
                               std::to_string(pixel % image.width) + ", " +
                               std::to_string(pixel / image.width) + "), channel " +
                               image.channelNames[i % image.channelNames.size()]);
    }
  }
  return image;
}

ImageComparison compareImages(const ExrImage& test, const std::string& testName,
                              const ExrImage& reference, const std::string& referenceName,
                              int blockSize) {
  if (test.width != reference.width || test.height != reference.height) {
    throw std::invalid_argument("images differ in size: '" + testName + "' is " +
                                std::to_string(test.width) + "x" + std::to_string(test.height) +
                                ", '" + referenceName + "' is " + std::to_string(reference.width) +
                                "x" + std::to_string(reference.height));
  }
  if (blockSize < 1 || blockSize > test.width || blockSize > test.height) {
    throw std::invalid_argument(
        "block size " + std::to_string(blockSize) + " must be between 1 and the smaller side (" +
        std::to_string(std::min(test.width, test.height)) + " pixels) of '" + testName + "'");
  }
  const std::vector<std::size_t> match = matchChannels(test, testName, reference, referenceName);
  ImageComparison comparison;
  comparison.blockSize = blockSize;
  comparison.blocksX = test.width / blockSize;
  comparison.blocksY = test.height / blockSize;
  bool anySpectral = false;
  for (const auto& name : test.channelNames)
    anySpectral = anySpectral || parseSpectralChannelName(name).has_value();
  DifferenceSums pooled;
  for (std::size_t c = 0; c < test.channelNames.size(); ++c) {
    DifferenceSums sums;
    for (int by = 0; by < comparison.blocksY; ++by) {
      for (int bx = 0; bx < comparison.blocksX; ++bx) {
        sums.add(blockMean(test, bx * blockSize, by * blockSize, blockSize, c),
                 blockMean(reference, bx * blockSize, by * blockSize, blockSize, match[c]));
      }
    }
    comparison.channels.push_back(finish(sums, test.channelNames[c], referenceName));
    if (!anySpectral || parseSpectralChannelName(test.channelNames[c])) {
      pooled.add(sums);
      ++comparison.overallChannelCount;
    }
  }
  comparison.overall = finish(pooled, "overall", referenceName);
  comparison.overall.wavelengthNm.reset();
  return comparison;
}

NoiseImage noiseImageOf(const ExrImage& image) {
  NoiseImage noise;
  noise.width = image.width;
  noise.height = image.height;
  std::vector<std::pair<std::size_t, double>> spectral;  // channel index, wavelength
  for (std::size_t c = 0; c < image.channelNames.size(); ++c)
    if (const auto w = parseSpectralChannelName(image.channelNames[c])) spectral.push_back({c, *w});
  std::vector<std::vector<std::size_t>> groups;
  auto inRange = [&](double lo, double hi) {
    std::vector<std::size_t> members;
    for (const auto& [c, w] : spectral)
      if (w >= lo - 1e-9 * lo && w <= hi + 1e-9 * hi) members.push_back(c);
    return members;
  };
  std::istringstream bands(image.attribute("hylios:bands"));
  std::string entry;
  while (std::getline(bands, entry, ';')) {
    const auto equals = entry.rfind('=');
    if (equals == std::string::npos) continue;
    const std::string name = entry.substr(0, equals);
    std::istringstream numbers(entry.substr(equals + 1));
    double lo = 0, hi = 0;
    char colon = 0;
    numbers >> lo;
    hi = lo;
    if (numbers >> colon && colon == ':') numbers >> hi;
    std::vector<std::size_t> members = inRange(lo, hi);
    if (members.empty())
      throw std::runtime_error("image has no spectral channel for band '" + name + "'");
    noise.groups.push_back("band " + name);
    groups.push_back(std::move(members));
  }
  if (groups.empty() && !spectral.empty()) {
    noise.groups.push_back("spectral mean");
    groups.push_back(inRange(0, INFINITY));
  }
  std::array<int, 3> rgbChannels{-1, -1, -1};
  if (image.attribute("hylios:rgb").rfind("linear sRGB", 0) == 0)
    for (int i = 0; i < 3; ++i) {
      const auto at =
          std::find(image.channelNames.begin(), image.channelNames.end(), std::string(1, "RGB"[i]));
      if (at != image.channelNames.end())
        rgbChannels[i] = static_cast<int>(at - image.channelNames.begin());
    }
  const bool colour = rgbChannels[0] >= 0 && rgbChannels[1] >= 0 && rgbChannels[2] >= 0;
  if (colour) {
    for (const char* name : {"R", "G", "B"}) noise.groups.push_back(name);
    noise.rgb = {static_cast<int>(groups.size()), static_cast<int>(groups.size()) + 1,
                 static_cast<int>(groups.size()) + 2};
  }
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      for (const auto& members : groups) {
        double sum = 0;
        for (std::size_t c : members) sum += image.value(x, y, c);
        noise.values.push_back(sum / static_cast<double>(members.size()));
      }
      if (colour)
        for (int i = 0; i < 3; ++i)
          noise.values.push_back(image.value(x, y, static_cast<std::size_t>(rgbChannels[i])));
    }
  return noise;
}

ImageComparison compareImageFiles(const std::filesystem::path& test,
                                  const std::filesystem::path& reference, int blockSize) {
  return compareImages(readExrImage(test), test.string(), readExrImage(reference),
                       reference.string(), blockSize);
}

std::string formatComparisonCsv(const ImageComparison& comparison) {
  std::ostringstream csv;
  csv << "channel,wavelength_nm,values_compared,rmse,reference_mean_abs,relative_rmse,mean_"
         "relative_difference\n";
  auto row = [&](const ChannelDifference& d) {
    csv << csvField(d.channel) << ","
        << (d.wavelengthNm ? formatNumber(*d.wavelengthNm) : std::string()) << ","
        << d.valuesCompared << "," << formatNumber(d.rmse) << ","
        << formatNumber(d.referenceMeanAbs) << "," << formatNumber(d.relativeRmse) << ","
        << formatNumber(d.meanRelativeDifference) << "\n";
  };
  for (const auto& channel : comparison.channels) row(channel);
  row(comparison.overall);
  return csv.str();
}

std::string formatComparisonTable(const ImageComparison& comparison) {
  std::ostringstream table;
  table << "compared " << comparison.blocksX << "x" << comparison.blocksY << " values per channel";
  if (comparison.blockSize > 1)
    table << " (means of " << comparison.blockSize << "x" << comparison.blockSize
          << " pixel blocks)";
  table << "; overall pools " << comparison.overallChannelCount << " channel(s)\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-18s %13s %13s %13s %13s\n", "channel", "rmse", "ref_mean_abs",
                "relative_rmse", "mean_rel_diff");
  table << line;
  auto row = [&](const ChannelDifference& d) {
    std::snprintf(line, sizeof line, "%-18s %13.6g %13.6g %13.6g %13.6g\n", d.channel.c_str(),
                  d.rmse, d.referenceMeanAbs, d.relativeRmse, d.meanRelativeDifference);
    table << line;
  };
  row(comparison.overall);
  for (const auto& channel : comparison.channels) row(channel);
  return table.str();
}

}  // namespace hylios
