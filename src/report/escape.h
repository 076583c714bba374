// Output safety of reports: the one place per output language where text that did not come
// from the program (scene, link, joint and point names, a scene's description, claim ids,
// statements, sources and notes of a user's claim file, file paths on the command line) is
// made inert.
//
// Renderers (report/render.h) pass every plain string of a Document (report/document.h)
// through the function of their language; only math spans and displayed equations, which
// builders make from the program's own TeX, are passed through as they are. So a builder must
// never put a user string into a math span: it goes into a plain span and is escaped here.
//
//   language      context                         function
//   HTML, SVG     text node, "..." attribute      html_escape
//   LaTeX         running text, command argument  latex_escape
//                 math mode (figure labels)       latex_math_escape
//                 verbatim listing                latex_verbatim
//                 \label key                      anchor_id
//   Markdown      inline text (headings, cells)   markdown_escape
//                 code block                      markdown_code_block
//                 <a id="..."> anchor             anchor_id
//   file names    figure files, report files      file_stem
//
// Each function maps text without special characters to itself, so a report of a benign scene
// is byte for byte what it was before escaping was added.
#pragma once

#include <cstddef>
#include <string>

namespace linkproof::report {

/// HTML and SVG (XML) text and double-quoted attribute values: & < > " become entities;
/// characters that XML 1.0 forbids (control characters other than tab, newline and carriage
/// return) and bytes that are not UTF-8 become U+FFFD, so a standalone SVG file stays
/// well-formed XML. No `<` of the input survives: the result holds no element.
std::string html_escape(const std::string& s);

/// LaTeX running text and command arguments (\section{...}, \caption{...}, table cells):
///   \ { } $ & % # _ ~ ^        escaped (\textbackslash{}, \{, ..., \textasciicircum{})
///   < >                        $<$, $>$ (OT1 has no glyph)
///   tab, newline, return       a space (a blank line would end a paragraph inside an argument)
///   other control characters   '?'
///   the Unicode characters reports use (omega, beta, <=, the section sign of the citations
///   "docs/conventions.md §A3", ...): their TeX; any other non-ASCII
///   character (or a byte that is not UTF-8): '?'
/// The result is ASCII, its braces balance, it starts no command of the input, and it holds no
/// ^^ (TeX's character-code notation) and no % (a comment would swallow the rest of the line).
std::string latex_escape(const std::string& s);

/// LaTeX math mode (the labels of a figure, `$K'_{1}$`): letters, digits, spaces and
/// ' - + . , ( ) / = : ; ! ? * | [ ] < > @ " pass; \ { } $ & % # _ ~ become \backslash, \{, \},
/// \$, \&, \%, \#, \_, \sim; ^ becomes \hat{} unless `superscript_ok` and it is the last but one
/// character followed by a letter or digit (the program's own "A_BA^t"); anything else '?'.
std::string latex_math_escape(const std::string& s, bool superscript_ok = false);

/// A whole `verbatim` environment (begin, lines, end) showing `code`. The content cannot close
/// it: a line is broken before the `}` that would complete `\end{verbatim}` (as lines longer
/// than 90 characters are folded). Control characters other than tab are shown as '?', line
/// ends (\n, \r\n, \r) end a line, the section sign is written "sec. " and other non-ASCII
/// characters are shown as '?' (pdflatex's inputenc stops at a character it has no glyph for).
std::string latex_verbatim(const std::string& code);

/// Markdown inline text (paragraphs, list items, table cells, headings, figure captions):
///   \ ` * _ < > | $ & # ~        backslash-escaped (no emphasis, code, raw HTML, cell break,
///                                math, entity, heading close or strikethrough)
///   ] before ( or [              backslash-escaped (no inline or reference link)
///   tab, newline, return         a space (a line break could start a heading, list or fence)
///   other control characters     '?'
/// At the start of a block (`block_start`): leading spaces are dropped (four would make an
/// indented code block) and a leading [ - + = or "1." / "1)" is escaped (no link definition,
/// list, setext underline or ordered list).
std::string markdown_escape(const std::string& s, bool block_start = false);

/// A fenced Markdown code block showing `code`: the fence is one backtick longer than the
/// longest run of backticks in the code (at least three), so no line of the code closes it.
std::string markdown_code_block(const std::string& code);

/// An anchor (HTML id, Markdown <a id>, LaTeX \label key) from a section or figure id: ASCII
/// letters, digits and . _ : - are kept, any other byte becomes "-xx" (its two hex digits).
/// "proof-dijksman1966.eq5" is kept as it is.
std::string anchor_id(const std::string& id);

/// Longest stem file_stem returns, in bytes: with ".html" or "-2.svg" the name stays far below
/// the 255 bytes file systems allow.
constexpr std::size_t kMaxFileStemBytes = 200;

/// A file name stem (no extension) from a scene name, figure id or input stem: ASCII letters,
/// digits and . _ + - are kept, any other character (a path separator /, \, a space, a
/// control character, a non-ASCII character) becomes '_'; leading dots and dashes are dropped
/// (no hidden file, no "..", nothing read as an option); a stem longer than kMaxFileStemBytes
/// is cut and ends in "-" and 16 hex digits of a hash of the whole name (two long names that
/// share a beginning stay distinct); an empty result is "unnamed". Deterministic; "pentagon"
/// is kept as it is. So a file written as dir / (file_stem(x) + ".svg") is always inside dir.
std::string file_stem(const std::string& name);

}  // namespace linkproof::report
