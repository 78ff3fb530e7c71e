// SPDX-License-Identifier: GPL-3.0-or-later
// SVG <text> redrawn in a Hershey single-stroke font (ImportOptions::textFont; docs/text.md,
// docs/svg-import.md): a pass over the document before the sanitiser that replaces each <text>
// element, in place, by a <g> holding <path>s of the text's strokes in the text's own user
// space, so that everything after it (transforms, clips, layers by group or colour, placement)
// treats them as drawn paths. The rest of the document is kept byte for byte and every line
// keeps its number (warnings still name the right line).
//
// What is followed: the x and y of <text> and <tspan> (their first value: per-glyph position
// lists are not), dx and dy, font-size (inherited, with its units), text-anchor (start, middle,
// end; per text chunk), the fill colour (else the stroke colour; "none" for both draws
// nothing), white space collapsed as CSS does. Every other attribute of the <text> (id, class,
// transform, style, clip-path, opacity...) moves onto the <g>. Not followed: style sheets'
// font-size/fill/text-anchor rules (only attributes and style=""), <textPath> (its text is
// dropped with a warning), rotate, textLength, letter- and word-spacing, vertical writing.
#pragma once

#include <QString>

#include <vector>

#include "core/support/message.hpp"
#include "core/text/hershey_font.hpp"

namespace fivebar::svg {

// The cap height of the single-stroke text as a fraction of its font size (em): about what
// common faces have (DejaVu Sans 0.73, Liberation Sans 0.72, Times 0.66).
inline constexpr double kTextCapHeightPerEm = 0.7;

// The document with its <text> elements redrawn; unchanged when it has none. Warnings
// (translatable, context "ImportWarning") for what is not drawn. dpi: user units per inch.
QString redrawTextInFont(const QString& document, const text::HersheyFont& font, double dpi,
                         std::vector<Message>& warnings);

}  // namespace fivebar::svg
