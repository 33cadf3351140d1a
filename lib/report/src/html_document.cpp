#include "isurface/report/html_document.h"

#include <cstdint>

namespace isurface::report {

std::string relativeLink(std::string_view fileName) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out = "./";
  for (const char c : fileName) {
    const auto byte = static_cast<unsigned char>(c);
    const bool unreserved = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                            c == '-' || c == '.' || c == '_' || c == '~';
    if (unreserved)
      out += c;
    else
      out += {'%', kHex[byte >> 4], kHex[byte & 15]};
  }
  return out;
}

// The length of the well-formed UTF-8 character at `at` (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF), 0 where the bytes are not one.
std::size_t utf8CharacterLength(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t k) { return at + k < text.size() ? static_cast<unsigned char>(text[at + k]) : 0u; };
  const unsigned lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned low = 0x80, high = 0xBF;  // the second byte's range
  if (lead >= 0xC2 && lead <= 0xDF) length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
  else return 0;
  if (byte(1) < low || byte(1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (byte(k) < 0x80 || byte(k) > 0xBF) return 0;
  return length;
}

std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (static_cast<unsigned char>(c) >= 0x80) {
      // A page that says it is UTF-8 holds only UTF-8: a file name in another encoding is shown
      // with replacement characters, as the JSON outputs show it.
      const std::size_t length = utf8CharacterLength(text, i);
      if (length == 0) {
        out += "\xEF\xBF\xBD";
      } else {
        out.append(text.substr(i, length));
        i += length - 1;
      }
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        // Control bytes of a program (a NUL, a lone carriage return) are not text.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t') out += "\xEF\xBF\xBD";
        else out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t(std::uint8_t(bytes[i])) << 16) | (std::uint32_t(std::uint8_t(bytes[i + 1])) << 8) |
                            std::uint8_t(bytes[i + 2]);
    out += kAlphabet[v >> 18], out += kAlphabet[(v >> 12) & 63], out += kAlphabet[(v >> 6) & 63], out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
    out += kAlphabet[v >> 18], out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

HtmlDocument::HtmlDocument(const std::string& title) : title_(title) {}

void HtmlDocument::heading(int level, const std::string& text, const std::string& id) {
  const std::string tag = "h" + std::to_string(level);
  body_ += "<" + tag + (id.empty() ? "" : " id=\"" + escapeHtml(id) + "\"") + ">" + escapeHtml(text) + "</" + tag + ">\n";
}

void HtmlDocument::paragraph(const std::string& text) { body_ += "<p>" + escapeHtml(text) + "</p>\n"; }

void HtmlDocument::table(const std::vector<std::vector<std::string>>& rows, const std::string& cssClass) {
  body_ += "<table" + (cssClass.empty() ? std::string() : " class=\"" + cssClass + "\"") + ">\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const char* cell = r == 0 ? "th" : "td";
    body_ += "<tr>";
    for (const std::string& text : rows[r]) body_ += std::string("<") + cell + ">" + escapeHtml(text) + "</" + cell + ">";
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

void HtmlDocument::image(const std::string& png, const std::string& caption, const std::string& cssClass) {
  body_ += "<figure" + (cssClass.empty() ? std::string() : " class=\"" + cssClass + "\"") +
           "><img alt=\"" + escapeHtml(caption) + "\" src=\"data:image/png;base64," + base64(png) + "\"><figcaption>" +
           escapeHtml(caption) + "</figcaption></figure>\n";
}

// A program line as a report shows it: a comment of megabytes is cut, not copied into the page,
// and never inside a UTF-8 character.
std::string shownLine(const std::string& text) {
  if (text.size() <= kLongestShownLine) return text;
  std::size_t cut = kLongestShownLine;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "\u2026 (" + std::to_string(text.size()) + " characters)";
}

void HtmlDocument::code(const std::vector<std::pair<std::uint32_t, std::string>>& numberedLines, std::uint32_t mark) {
  body_ += "<pre class=\"gcode\">";
  for (const auto& [number, text] : numberedLines) {
    const bool marked = number == mark;
    body_ += std::string(marked ? "<mark>" : "") + "<span class=\"ln\">" + std::to_string(number) + "</span>" +
             escapeHtml(shownLine(text)) + (marked ? "</mark>" : "") + "\n";
  }
  body_ += "</pre>\n";
}

void HtmlDocument::openSection(const std::string& id, const std::string& cssClass) {
  body_ += "<section id=\"" + escapeHtml(id) + "\"" + (cssClass.empty() ? "" : " class=\"" + cssClass + "\"") + ">\n";
}

void HtmlDocument::closeSection() { body_ += "</section>\n"; }

std::string HtmlDocument::finish() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escapeHtml(title_) +
         "</title>\n<style>\n"
         "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:2em auto;max-width:1100px;color:#222;line-height:1.4}\n"
         "h1{border-bottom:2px solid #2c6fbb}h2{margin-top:1.6em;border-bottom:1px solid #ccc}\n"
         "table{border-collapse:collapse;margin:.6em 0}th,td{border:1px solid #bbb;padding:.25em .6em;text-align:left}\n"
         "th{background:#eef3fa}td.num{text-align:right}\n"
         ".maps{display:flex;flex-wrap:wrap;gap:1em}.maps figure{flex:1 1 45%;max-width:49%}figure{margin:.4em 0}figure img{max-width:100%;border:1px solid #ddd}\n"
         "figcaption{font-size:.85em;color:#555}\n"
         "pre.gcode{background:#f7f7f7;border:1px solid #ddd;padding:.5em;font-size:.85em;overflow-x:auto}\n"
         "pre.gcode .ln{display:inline-block;width:4.5em;color:#888;user-select:none}mark{background:#ffe08a}\n"
         ".near{background:#fde2e1}\n"
         "@media print{body{max-width:none;margin:0}section{page-break-inside:avoid}h2{page-break-before:auto}}\n"
         "</style>\n</head>\n<body>\n" +
         body_ + "</body>\n</html>\n";
}

}  // namespace isurface::report
