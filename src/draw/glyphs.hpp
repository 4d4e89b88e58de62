// The measured size of a label's words on the page: SVG's DejaVu Sans and TikZ's Computer Modern,
// from tables of the fonts' own glyph metrics (glyphs_table.cpp, written by glyphs_table.py).
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace kinergy::draw::detail {

struct SvgGlyph {
  unsigned cp;
  float advance, bottom, top;  // ems; y up from the baseline
};
struct TexChar {
  float wd, ht, dp, ic;  // ems of the design size
};
struct TexFont {
  const char* name;
  double size;         // design size, pt
  double quad, space;  // ems: the quad (18 mu, in cmsy) and the interword space
  /// The symbol font's (cmsy) placing of scripts, in ems: x-height, sup2, sub1, sub2, sup_drop,
  /// sub_drop, axis height (The TeXbook's σ5, σ14, σ16, σ17, σ18, σ19, σ22); zero elsewhere.
  double xheight, sup2, sub1, sub2, sup_drop, sub_drop, axis;
  TexChar c[128];
};
struct TexKern {
  unsigned font, left, right;  // font: its index in kTexFonts
  float kern;                  // ems
};
extern const SvgGlyph kDejaVuSans[];
extern const std::size_t kDejaVuSansCount;
extern const TexFont kTexFonts[];
extern const std::size_t kTexFontCount;
extern const TexKern kTexKerns[];
extern const std::size_t kTexKernCount;

/// A label's text in parts, each plain or a subscript: what follows a '_' (up to the next space
/// or '_') is a subscript, as a textbook sets "m_cart v̄_cart" or "W_A".
std::vector<std::pair<std::string, bool>> label_parts(const std::string& text);

/// A line of words from its starting point on the baseline: its advance, and how far its ink
/// reaches above and below the baseline.
struct Extent {
  double width = 0, above = 0, below = 0;
};

/// An SVG label's text ("m_A v̄_A": a '_' starts a subscript) set as svg_label_text sets it:
/// DejaVu Sans at `px` pixels, subscripts at kSubFont px lowered by kSubDrop px. In pixels.
Extent svg_extent(const std::string& text, double px = 13);
constexpr double kSubFont = 10, kSubDrop = 4;

/// A label in TeX's math mode ("m_{A}\bar{v}_{A}") set at `pt` points (9: \footnotesize of an
/// 11 pt document, 10: \small), as TeX sets it: Computer Modern, subscripts a script size. In
/// points. The TeX a label holds: letters and digits, Greek letters, \bar, \mathrm, \mathbf,
/// \int, \Delta, spacing commands, _{...}, ^{...}, and = + − ( ) , . ; others are measured as an
/// italic letter each.
Extent tex_extent(const std::string& tex, double pt);
/// A label in TeX's text mode as tex_label_text writes it (roman, "W$_{\mathrm{cart}}$"), in points.
Extent tex_text_extent(const std::string& text, double pt);

}  // namespace kinergy::draw::detail
