// The HTML document writer (html_writer.hpp).
#include "html_writer.hpp"

#include <set>

#include "../cli_error.hpp"
#include "markup_escape.hpp"

namespace frictionref::cli {

HtmlWriter::HtmlWriter() {
  out_ = "<!DOCTYPE html>\n";
  open("html", {{"lang", "en"}});
  out_ += '\n';
}

void HtmlWriter::start_tag(std::string_view tag, const Attributes& attributes) {
  out_ += '<';
  out_ += tag;
  for (const auto& [name, value] : attributes) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    out_ += escape_markup(value);
    out_ += '"';
  }
  out_ += '>';
}

void HtmlWriter::open(std::string_view tag, const Attributes& attributes) {
  start_tag(tag, attributes);
  open_.emplace_back(tag);
}

void HtmlWriter::close(std::string_view tag) {
  if (open_.empty() || open_.back() != tag)
    throw internal_error("HTML writer: closing <" + std::string(tag) + "> inside <" +
                         (open_.empty() ? std::string("nothing") : open_.back()) + ">");
  out_ += "</";
  out_ += tag;
  out_ += '>';
  // Rows and blocks end their line: the source stays readable (cells and
  // inline elements stay on it, so a row reads as one line).
  static const std::set<std::string_view> line_ends = {
      "html",  "head", "title", "style", "body",   "header",    "main",  "footer",
      "h1",    "h2",   "h3",    "p",     "ul",     "li",        "table", "thead",
      "tbody", "tr",   "div",   "pre",   "figure", "figcaption"};
  if (line_ends.count(tag) > 0) out_ += '\n';
  open_.pop_back();
}

void HtmlWriter::void_element(std::string_view tag, const Attributes& attributes) {
  start_tag(tag, attributes);
  out_ += '\n';
}

void HtmlWriter::element(std::string_view tag, std::string_view text,
                         const Attributes& attributes) {
  open(tag, attributes);
  this->text(text);
  close(tag);
}

void HtmlWriter::text(std::string_view text) { out_ += escape_markup(text); }

void HtmlWriter::raw(std::string_view markup) { out_ += markup; }

std::string HtmlWriter::finish() {
  close("html");
  if (!open_.empty()) throw internal_error("HTML writer: <" + open_.back() + "> left open");
  return std::move(out_);
}

}  // namespace frictionref::cli
