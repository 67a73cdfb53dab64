#include "renderer/image/image_file.h"

#include <dlfcn.h>
#include <stdexcept>
#include <system_error>

#include "renderer/image/oiio/image_io_module.h"

namespace hylios {
namespace {
namespace fs = std::filesystem;

constexpr const char* kModuleFileName = "libhylios_image_io.so";

/// Where the module may be: beside the file holding this code, beside the executable, and where
/// the build put it (each once, in that order).
std::vector<fs::path> moduleCandidates() {
  std::vector<fs::path> candidates;
  const auto add = [&candidates](const fs::path& directory) {
    std::error_code error;
    const fs::path dir = fs::weakly_canonical(directory, error);
    if (error || dir.empty()) return;
    const fs::path candidate = dir / kModuleFileName;
    for (const fs::path& known : candidates)
      if (known == candidate) return;
    candidates.push_back(candidate);
  };
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&moduleCandidates), &info) != 0 && info.dli_fname &&
      info.dli_fname[0] == '/')
    add(fs::path(info.dli_fname).parent_path());
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) add(executable.parent_path());
#ifdef HYLIOS_IMAGE_IO_MODULE
  add(fs::path(HYLIOS_IMAGE_IO_MODULE).parent_path());
#endif
  return candidates;
}

const ImageIoModule& loadModule() {
  std::string tried;
  for (const fs::path& candidate : moduleCandidates()) {
    std::error_code error;
    if (!fs::exists(candidate, error)) {
      tried += "\n  " + candidate.string() + " (not there)";
      continue;
    }
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* message = dlerror();
      tried += "\n  " + candidate.string() + " (" + (message ? message : "cannot be loaded") + ")";
      continue;
    }
    using Entry = const ImageIoModule* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, "hyliosImageIoModule"));
    const ImageIoModule* module = entry ? entry() : nullptr;
    if (module && module->abi == kImageIoModuleAbi && module->size == sizeof(ImageIoModule))
      return *module;  // kept loaded for the life of the process
    tried += "\n  " + candidate.string() + " (another build of hylios: its interface differs)";
    dlclose(handle);
  }
  throw std::runtime_error(
      std::string("cannot load the image-file module ") + kModuleFileName +
      " (OpenImageIO), needed to read or write images; tried:" + tried +
      "\nBuild it with the hylios executable (cmake --build build --target hylios).");
}

const ImageIoModule& module() {
  static const ImageIoModule& loaded = loadModule();
  return loaded;
}
}  // namespace

std::string StoredImage::attribute(const std::string& name) const {
  for (const auto& [key, value] : stringAttributes)
    if (key == name) return value;
  return std::string();
}

bool tryReadImageFile(const fs::path& path, StoredImage& image, std::string& error) {
  return module().read(path.string(), image, error);
}

StoredImage readImageFile(const fs::path& path) {
  StoredImage image;
  std::string error;
  if (!tryReadImageFile(path, image, error))
    throw std::runtime_error("cannot read image '" + path.string() + "': " + error);
  return image;
}

void writeImageFile(const fs::path& path, ImageFileFormat format, const ImageToWrite& image,
                    const std::vector<ImageAttribute>& attributes, const fs::path& namedAs) {
  const std::string name = (namedAs.empty() ? path : namedAs).string();
  const bool png = format == ImageFileFormat::Png8;
  if (!image.channelNames || image.width <= 0 || image.height <= 0 ||
      (png ? image.bytes == nullptr : image.pixels == nullptr))
    throw std::invalid_argument("writeImageFile '" + name +
                                "': no pixels of the format's type, or no channel names");
  std::string error;
  if (!module().write(path.string(), format, image, attributes, error))
    throw std::runtime_error("cannot write '" + name + "': " + error);
}

int imageTextWidth(const std::string& text, int fontSizePx, const std::string& font) {
  return module().textWidth(text, fontSizePx, font);
}

bool drawImageText(float* rgb, int width, int height, int x, int baselineY, const std::string& text,
                   int fontSizePx, const std::string& font, int anchor) {
  return module().drawText(rgb, width, height, x, baselineY, text, fontSizePx, font, anchor);
}

}  // namespace hylios
