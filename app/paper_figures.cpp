#include "app/paper_figures.h"

namespace hylios {

// Quotes from the paper "On the Hyperspectral Modeling of Light Interaction
// with Human Skin" (HyLIoS), figure captions and Sec. 5 "Results and Discussion".
const std::vector<PaperFigure>& paperFigures() {
  static const std::vector<PaperFigure> figures = {
      {1,
       "ultraviolet, visible and infrared",
       {"scenes/figure01_uv365.toml", "scenes/figure01_visible.toml",
        "scenes/figure01_ir1100.toml"},
       "Images showing distinct skin appearance features in the ultraviolet (left), visible "
       "(middle) and infrared (right) spectral domains. […] The ultraviolet and infrared "
       "responses (at 365 nm and 1100 nm, respectively) are depicted using pseudo color.",
       "the subject's freckles are accentuated under exposure to UV light (Figure 1(Left)) and "
       "imperceptible under exposure to IR light (Figure 1(Right)).",
       PaperTrend::Freckles},
      {12,
       "epidermal melanin in the visible",
       {"scenes/figure12_melanin1.5.toml", "scenes/figure12_melanin7.toml",
        "scenes/figure12_melanin30.toml"},
       "Images generated using the HyLIoS model to illustrate the effects of increased melanin "
       "pigmentation on the appearance attributes of human skin in the visible domain. Left: "
       "1.5%. Middle: 7%. Right: 30%.",
       "an increase in epidermal melanin content leading to visible darker skin tones […] while "
       "an increase in epidermal melanin content from 7% to 30% results in a darker skin "
       "appearance in the visible domain (Figure 12)",
       PaperTrend::Decreasing},
      {13,
       "epidermal melanin at 365 nm",
       {"scenes/figure13_melanin1.5.toml", "scenes/figure13_melanin7.toml",
        "scenes/figure13_melanin30.toml"},
       "Images generated using the HyLIoS model to illustrate the reductional effects of "
       "increased melanin pigmentation on skin spectral responses in the UV domain. Left: 1.5%. "
       "Middle: 7%. Right: 30%. The UV responses (at 365 nm) are depicted in pseudo color.",
       "such a change in appearance [7% to 30%] is negligible within the UV domain (Figure 13).",
       PaperTrend::SmallStep},
      {14,
       "dehydration at 1650 nm",
       {"scenes/figure14_water0.toml", "scenes/figure14_water20.toml",
        "scenes/figure14_water40.toml"},
       "Images generated using the HyLIoS model to illustrate the magnifying effects of "
       "dehydration on skin spectral responses in the IR domain. […] a light pigmented specimen "
       "(1.5% epidermal melanin content) […] Left: No reduction. Middle: 20% reduction. Right: "
       "40% reduction. The IR responses (at 1650 nm) are depicted in pseudo color.",
       "A reduction of water content in the cutaneous tissues [Bla52], in turn, results in an "
       "increase in skin reflectance in the IR domain [APS*02]. As illustrated by the images "
       "presented in Figure 14, this qualitative behavior is also captured by the proposed "
       "model.",
       PaperTrend::Increasing},
  };
  return figures;
}

}  // namespace hylios
