#pragma once
/// @file html_report.hpp
/// One self-contained HTML page for a report (`gap --report`, `identify --report`): the
/// verdict first, then headings, tables, text and the plots embedded as data: URIs, so the
/// single file can be mailed or archived without its directory. All text is HTML-escaped.

#include <string>
#include <vector>

namespace hstmon::sim {

/// How the verdict block is coloured.
enum class VerdictTone {
  kGood,     ///< green: nothing to act on
  kWarning,  ///< amber: usable, with a caveat
  kBad,      ///< red: the result does not hold
  kNeutral,  ///< grey: information only
};

/// `text` with &, <, >, " and ' replaced by entities.
std::string html_escape(const std::string& text);

/// `bytes` in base64 (RFC 4648, with padding).
std::string base64(const std::string& bytes);

/// Builds the page in memory; write() puts it in a file.
class HtmlReport {
 public:
  /// @param title  the page's title and first heading
  explicit HtmlReport(std::string title);

  /// The verdict, shown right under the title whenever it is set.
  void verdict(const std::string& text, VerdictTone tone);
  /// A section heading.
  void heading(const std::string& text);
  /// A paragraph of plain text.
  void paragraph(const std::string& text);
  /// Text kept as written (fixed-width), e.g. the command's own text report.
  void preformatted(const std::string& text);
  /// A table; rows shorter than the header are padded with empty cells.
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  /// Embeds a PNG or SVG file as a data: URI, with a caption. If the file cannot be read
  /// or is empty, the page says so in its place.
  /// @return empty on success, else why the image is missing
  std::string image(const std::string& file, const std::string& caption);

  /// The whole page.
  std::string html() const;
  /// Writes the page to `path`.
  /// @return empty on success, else why not
  std::string write(const std::string& path) const;

 private:
  std::string title_;
  std::string verdict_;
  VerdictTone tone_ = VerdictTone::kNeutral;
  std::string body_;
};

}  // namespace hstmon::sim
