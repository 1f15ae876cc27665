// bezel/text.hpp — text to pixels, all of it: the umbrella of the text module's headers.
//
//   bezel/shape.hpp          UTF-8, OpenType features, HarfBuzz shaping of one run (Shaper)
//   bezel/font_collection.hpp  a list of fonts, each cluster from the first that covers it
//   bezel/layout.hpp         paragraphs into lines: breaks, wrapping, bidi order (layout_text)
//   bezel/glyph.hpp          glyphs into caller buffers (GlyphRasterizer) and a bounded GlyphCache
//   bezel/text_renderer.hpp  the one-call renderer of a paragraph onto a page (TextRenderer)
//   bezel/font_info.hpp      what a font file says about itself (font_info)
#pragma once

#include "bezel/font_collection.hpp"
#include "bezel/font_info.hpp"
#include "bezel/glyph.hpp"
#include "bezel/layout.hpp"
#include "bezel/shape.hpp"
#include "bezel/text_renderer.hpp"
