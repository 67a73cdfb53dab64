#include "app/gallery_report.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "renderer/scene/data_paths.h"

namespace hylios {
namespace {

std::string percent(double fraction) { return fmt::format("{:.1f} %", 100 * fraction); }

/// "±0.0012" style: the number with 3 significant digits, and its standard error.
std::string withError(double value, double error) {
  return fmt::format("{:.4g} ± {:.2g}", value, error);
}

/// A scene path as the reader of docs/ sees it: relative to the data root when inside it.
std::string sceneName(const std::filesystem::path& scene) {
  std::error_code error;
  const auto relative = std::filesystem::relative(scene, dataRoot(), error);
  if (!error && !relative.empty() && relative.native().rfind("..", 0) != 0)
    return relative.generic_string();
  return scene.generic_string();
}

/// The relative change from panel a to panel b, with its standard error (independent means).
struct Change {
  double relative = 0, standardError = 0;
};
Change change(const PanelMean& a, const PanelMean& b) {
  Change c;
  if (!(a.mean > 0)) return c;
  const double ratio = b.mean / a.mean;
  c.relative = ratio - 1;
  c.standardError = std::fabs(ratio) * std::hypot(a.standardError / a.mean,
                                                  b.mean != 0 ? b.standardError / b.mean : 0.0);
  return c;
}

std::string changeText(const Change& c) {
  return fmt::format("{:+.1f} % (± {:.1f} %)", 100 * c.relative, 100 * c.standardError);
}

/// The steps between consecutive panels: "a → b: −12.0 % (± 0.3 %), …".
std::string stepsText(const FigureResult& r, std::vector<Change>& changes) {
  std::string text;
  for (std::size_t i = 1; i < r.panels.size(); ++i) {
    changes.push_back(change(r.panels[i - 1].head, r.panels[i].head));
    text += fmt::format("{}{} → {}: {}", i > 1 ? "; " : "", r.panels[i - 1].caption,
                        r.panels[i].caption, changeText(changes.back()));
  }
  return text;
}

const GalleryFigure* figureNumber(const std::vector<GalleryFigure>& all, int number) {
  for (const GalleryFigure& f : all)
    if (f.paper.number == number) return &f;
  return nullptr;
}

}  // namespace

std::string trendVerdict(const GalleryFigure& figure, const std::vector<GalleryFigure>& all) {
  const FigureResult& r = figure.result;
  if (r.panels.empty()) return "No panels were rendered.";
  std::vector<Change> changes;
  switch (figure.paper.check) {
    case PaperTrend::Freckles: {
      std::string text =
          "Freckle contrast (1 − mean on freckles / mean on clear skin, head pixels):";
      for (const FigurePanel& p : r.panels) {
        if (!p.freckles) continue;
        text += fmt::format(" {} {} ({} freckle, {} clear pixels);", p.caption,
                            withError(p.freckles->contrast, p.freckles->standardError),
                            p.freckles->frecklePixels, p.freckles->clearPixels);
      }
      const FigurePanel& first = r.panels.front();
      const FigurePanel& last = r.panels.back();
      if (first.freckles && last.freckles) {
        const bool follows = first.freckles->contrast >
                             last.freckles->contrast + 3 * std::hypot(first.freckles->standardError,
                                                                      last.freckles->standardError);
        text += follows
                    ? " the freckles stand out more in the UV than in the IR, as the paper says."
                    : " the freckles do **not** stand out more in the UV than in the IR.";
      }
      return text;
    }
    case PaperTrend::Decreasing:
    case PaperTrend::Increasing: {
      const std::string steps = stepsText(r, changes);
      const bool down = figure.paper.check == PaperTrend::Decreasing;
      bool follows = !changes.empty();
      for (const Change& c : changes)
        follows = follows &&
                  (down ? c.relative < -3 * c.standardError : c.relative > 3 * c.standardError);
      return fmt::format("Mean {} on the head, step by step: {}. {}", r.panels[0].quantity, steps,
                         follows ? (down ? "Every step is darker (beyond 3 standard errors), as "
                                           "the paper says."
                                         : "Every step is brighter (beyond 3 standard errors), "
                                           "as the paper says.")
                                 : "The means do **not** follow the paper's trend at every step.");
    }
    case PaperTrend::SmallStep: {
      const std::string steps = stepsText(r, changes);
      std::string text =
          fmt::format("Mean {} on the head, step by step: {}.", r.panels[0].quantity, steps);
      const GalleryFigure* visible = figureNumber(all, 12);
      if (!changes.empty() && visible && visible->result.panels.size() == r.panels.size()) {
        const auto& vp = visible->result.panels;
        const Change v = change(vp[vp.size() - 2].head, vp.back().head);
        const double uv = std::fabs(changes.back().relative), vis = std::fabs(v.relative);
        text += fmt::format(
            " The last step changes the mean by {} here against {} in the visible (Figure 12): ",
            changeText(changes.back()), changeText(v));
        text += uv < 0.5 * vis ? "less than half as much, the paper's \"negligible\" in kind."
                               : "**not** much less than in the visible, unlike the paper.";
      }
      return text;
    }
  }
  return "";
}

std::string galleryMarkdown(const std::vector<GalleryFigure>& figures, const GalleryRun& run) {
  std::string md =
      "# The paper's figures\n\n"
      "Figures 1, 12, 13 and 14 of \"On the Hyperspectral Modeling of Light Interaction with Human "
      "Skin\" (HyLIoS) rendered by hylios from the scene files in `scenes/`. This file and the "
      "sheets in "
      "`figures/` beside it are written by\n\n```sh\n" +
      run.command +
      "\n```\n\n"
      "(`" +
      run.settings +
      "`). Panels are ordered and captioned by what varies between a figure's scenes "
      "(app/figure_layout.h), not by file name. Pseudo-colour panels map radiance linearly onto "
      "the colour bar beneath them, one fixed scale per figure; radiance is relative: 1 is the "
      "radiance of a white diffuser under a uniform environment of emission scale 1 (the scenes "
      "light the head with a key area light of scale 8 and an environment of scale 0.15, hidden "
      "from the camera: `camera_visible = false`, docs/scene-format.md). Visible panels are sRGB; "
      "their number is the luminance Y on the same scale. Each panel's mean is taken over the "
      "pixels whose centre ray meets the head; its standard error comes from the film's two "
      "halves (alternating blocks of four samples, app/figure_job.h). Noise is the film's own "
      "estimate of the "
      "median per-pixel relative noise over the head (the worst of its groups: band, R, G, B, "
      "chromaticity; renderer/image/render_noise.h).\n";
  for (const GalleryFigure& f : figures) {
    md += fmt::format("\n## Figure {}: {}\n\n![Figure {}]({})\n\n", f.paper.number, f.paper.subject,
                      f.paper.number, f.sheetImage);
    md += "Paper, caption of Fig. " + std::to_string(f.paper.number) + ": \"" + f.paper.caption +
          "\"\n\nPaper, Sec. 5: \"" + f.paper.trend + "\"\n\n";
    md +=
        "| panel | scene | spp | noise | mean on the head ± SE | CPU s |\n"
        "|---|---|---|---|---|---|\n";
    for (const FigurePanel& p : f.result.panels)
      md += fmt::format("| {} | `{}` | {} | {} | {} {} | {:.1f} |\n", p.caption, sceneName(p.scene),
                        p.samplesPerPixel, percent(p.noise), p.quantity,
                        withError(p.head.mean, p.head.standardError), p.cpuSeconds);
    md += "\nMeasured: " + trendVerdict(f, figures) + "\n";
  }
  md += fmt::format(
      "\n## How it was run\n\n{} figures, {:.0f} s wall, {:.0f} CPU s (user + sys, all threads) "
      "on {} cores; 1-minute load average {:.2f} before and {:.2f} after (a shared machine: the "
      "wall time depends on the load, the CPU time much less).\n",
      figures.size(), run.wallSeconds, run.cpuSeconds, run.cores, run.loadBefore, run.loadAfter);
  return md;
}

}  // namespace hylios
