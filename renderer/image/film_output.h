// Writing a film: one multi-band OpenEXR in the spectral layout of Fichet, Pacanowski & Wilkie
// (JCGT 10(3), 2021) — channels "S0.<wavelength with comma decimal separator>nm" (the channel
// means, float) plus R, G, B preview channels, attributes spectralLayoutVersion = "1.0" and
// emissiveUnits = "W.m^-2.sr^-1", "hylios:spp" and "hylios:sppTarget" (int), "hylios:exposure",
// "hylios:rgb" (what R, G, B hold) and "hylios:bands" ("name=365;visible=380:780:10": each band's
// wavelengths), plus a channel "A" (1 where the pixel's centre ray sees a shape that does not emit,
// else 0) when the renderer set the film's coverage — and PNG previews beside it, one per band,
// named <stem>_<band>.png:
//   * a colour band (a range covering 400–700 nm): XYZ = k·Σ_i L(λ_i)·cmf(λ_i)·Δλ over its channels
//     (CIE 1931 2°, Δλ = the band's step), k = colourBandNormalisation(); XYZ → linear sRGB (D65
//     white); × film exposure; sRGB transfer, clamped to [0, 1]. R, G, B of the EXR are the same
//     linear sRGB × exposure (before the transfer); without a colour band they hold the first
//     band's radiance as grey (no exposure).
//   * any other band (single wavelength, or a range: the mean over its channels): the value mapped
//     linearly from the band's fixed [previewMin, previewMax] onto the colour map (magma), with a
//     colour bar strip below (ticks at min, middle, max; min/max and "radiance at <wavelength>" as
//     text when OpenImageIO can render text — otherwise the numbers go to <stem>_<band>_scale.txt).
// Any NaN/Inf in the film (or a value beyond float) is an error and nothing is written. Every file
// is written to a temporary name and renamed (never half-written).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/image/render_noise.h"

namespace hylios {

/// "S0.365,000000nm" for 365 nm.
std::string spectralChannelName(double wavelengthNm);
/// The wavelength of a spectral channel name ("S0.365,000000nm" → 365), or nothing when the name
/// is not an emissive spectral channel (e.g. "R").
std::optional<double> parseSpectralChannelName(const std::string& name);

/// Whether a band gets the colour (sRGB) preview: a range band covering at least 400–700 nm.
bool isColourBand(const BandDesc& band);
/// The colour normalisation of a colour band: k = 1 / Σ_i S(λ_i)·ȳ(λ_i)·Δλ over the band's
/// channels with S = D65/100 (the scene's "d65" emission of scale 1, 1 at 560 nm), so that a
/// pixel whose spectral radiance is S — a white diffuser under a uniform D65 environment of
/// scale 1 — has Y = 1 (and R = G = B ≈ 1 before exposure).
double colourBandNormalisation(const BandDesc& band);

/// Writes `exrPath` and the previews; returns every file written (EXR first). The EXR header gets
/// "hylios:spp" (samples per pixel done) and "hylios:sppTarget" (the film's target; less when a
/// render was stopped early), plus `extraAttributes` as string attributes (name → value, e.g.
/// "hylios:seed"). An `exrPath` that exists and is not a regular file (a device such as /dev/null,
/// a FIFO) is written in place and gets no previews.
std::vector<std::filesystem::path> writeFilmOutputs(
    const Film& film, const std::filesystem::path& exrPath,
    const std::vector<std::pair<std::string, std::string>>& extraAttributes = {});

/// The film from its first (secondHalf = false) or second half's samples alone, reduced to the
/// groups of renderer/image/render_noise.h: each band's mean radiance, and R, G, B of a colour
/// band.
NoiseImage filmHalfNoiseImage(const Film& film, bool secondHalf);
/// Per pixel and group of filmHalfNoiseImage, the second half's share q of the samples of the
/// group's channels (a colour band's for R, G, B; 0 where there is none).
std::vector<double> filmSecondHalfShare(const Film& film);
/// The film's own noise estimate: the two halves compared and weighed by their shares
/// (measureHalvesNoise: the noise of the whole film), over its coverage mask.
std::vector<GroupNoise> filmNoise(const Film& film);

/// Pastes PNG panels side by side in a grid with their labels under them (a contact sheet), under
/// `titleLines` (each centred; none: no title). Without text rendering the labels and title go to
/// <out stem>.labels.txt.
void writeContactSheet(const std::vector<std::filesystem::path>& panels,
                       const std::vector<std::string>& labels, const std::filesystem::path& out,
                       int columns, const std::vector<std::string>& titleLines = {});

}  // namespace hylios
