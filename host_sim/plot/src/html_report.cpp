/// @file html_report.cpp
#include "hstmon_plot/html_report.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>

namespace hstmon::sim {

namespace {

bool ends_with(const std::string& s, const std::string& x) {
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

const char* tone_class(VerdictTone t) {
  switch (t) {
    case VerdictTone::kGood: return "good";
    case VerdictTone::kWarning: return "warning";
    case VerdictTone::kBad: return "bad";
    case VerdictTone::kNeutral: return "neutral";
  }
  return "neutral";
}

const char* const kStyle =
    "body{font-family:sans-serif;max-width:1250px;margin:1.5em auto;padding:0 1em;color:#222}"
    "h1{font-size:1.5em}h2{font-size:1.2em;margin-top:1.6em;border-bottom:1px solid #ccc}"
    ".verdict{padding:.8em 1em;border-left:.5em solid;font-size:1.1em;margin:1em 0}"
    ".good{background:#e8f5e9;border-color:#2e7d32}.warning{background:#fff8e1;border-color:#f9a825}"
    ".bad{background:#ffebee;border-color:#c62828}.neutral{background:#f5f5f5;border-color:#9e9e9e}"
    "table{border-collapse:collapse;margin:.5em 0}th,td{border:1px solid #ccc;padding:.25em .6em}"
    "td{text-align:right;font-variant-numeric:tabular-nums}td:first-child,td.text{text-align:left}th{background:#f0f0f0}"
    "pre{background:#f7f7f7;padding:.8em;overflow-x:auto;font-size:.85em}"
    "figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}figcaption{color:#555}"
    ".missing{color:#c62828}";

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned>(static_cast<unsigned char>(bytes[i])) << 16 |
                       static_cast<unsigned>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                       static_cast<unsigned>(static_cast<unsigned char>(bytes[i + 2]));
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += i + 1 < bytes.size() ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::verdict(const std::string& text, VerdictTone tone) {
  verdict_ = text;
  tone_ = tone;
}

void HtmlReport::heading(const std::string& text) { body_ += "<h2>" + html_escape(text) + "</h2>\n"; }

void HtmlReport::paragraph(const std::string& text) { body_ += "<p>" + html_escape(text) + "</p>\n"; }

void HtmlReport::preformatted(const std::string& text) { body_ += "<pre>" + html_escape(text) + "</pre>\n"; }

void HtmlReport::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  body_ += "<table>\n<tr>";
  for (const auto& h : header) body_ += "<th>" + html_escape(h) + "</th>";
  body_ += "</tr>\n";
  for (const auto& row : rows) {
    body_ += "<tr>";
    for (std::size_t k = 0; k < std::max(header.size(), row.size()); ++k) {
      const std::string cell = k < row.size() ? row[k] : std::string();
      // Numbers align right (digits under digits); words and lists read better left-aligned.
      const bool number = cell.empty() || std::string("0123456789+-.").find(cell[0]) != std::string::npos;
      body_ += (number ? "<td>" : "<td class=\"text\">") + html_escape(cell) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

std::string HtmlReport::image(const std::string& file, const std::string& caption) {
  std::string bytes;
  {
    // Through a stringstream: GCC 12's -Wnull-dereference misfires on istreambuf_iterator.
    std::ifstream in(file, std::ios::binary);
    std::ostringstream data;
    data << in.rdbuf();
    bytes = data.str();
  }
  const char* type = ends_with(file, ".svg") ? "image/svg+xml" : ends_with(file, ".png") ? "image/png" : nullptr;
  std::string err;
  if (type == nullptr) {
    err = "not a .png or .svg file: " + file;
  } else if (bytes.empty()) {
    err = "missing or empty: " + file;
  }
  if (!err.empty()) {
    body_ += "<p class=\"missing\">plot " + html_escape(caption) + ": " + html_escape(err) + "</p>\n";
    return err;
  }
  body_ += "<figure><img alt=\"" + html_escape(caption) + "\" src=\"data:" + type + ";base64," + base64(bytes) +
           "\"><figcaption>" + html_escape(caption) + "</figcaption></figure>\n";
  return {};
}

std::string HtmlReport::html() const {
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                     html_escape(title_) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" +
                     html_escape(title_) + "</h1>\n";
  if (!verdict_.empty()) {
    page += std::string("<div class=\"verdict ") + tone_class(tone_) + "\" id=\"verdict\"><strong>Verdict:</strong> " +
            html_escape(verdict_) + "</div>\n";
  }
  return page + body_ + "</body>\n</html>\n";
}

std::string HtmlReport::write(const std::string& path) const {
  std::ofstream out(path, std::ios::binary);
  if (!out) return "cannot write " + path;
  out << html();
  out.close();
  if (!out) return "cannot write " + path;
  return {};
}

}  // namespace hstmon::sim
