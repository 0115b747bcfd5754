#include "analysis/report.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "engine/image/image_io.h"

namespace facet::analysis {

void Report::heading(const std::string& title) { markdown_ += "\n## " + title + "\n\n"; }

void Report::paragraph(const std::string& text) { markdown_ += text + "\n\n"; }

void Report::image(const std::string& relativePath, const std::string& caption) {
  markdown_ += "![" + caption + "](" + relativePath + ")\n\n";
}

void Report::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string text = "|";
    for (const std::string& c : cells) text += " " + c + " |";
    return text + "\n";
  };
  markdown_ += line(header);
  markdown_ += line(std::vector<std::string>(header.size(), "---"));
  for (const auto& row : rows) markdown_ += line(row);
  markdown_ += "\n";
}

void Report::write(const std::filesystem::path& path, const std::string& title) const {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    out << "# " << title << "\n" << markdown_;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  });
}

void writeCsv(const std::filesystem::path& path, const std::vector<std::string>& header,
              const std::vector<std::vector<std::string>>& rows) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    auto line = [&](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
      out << "\n";
    };
    line(header);
    for (const auto& row : rows) line(row);
    if (!out) throw std::runtime_error("cannot write " + path.string());
  });
}

std::string cell(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string formatted(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace facet::analysis
