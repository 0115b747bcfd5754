// What the analyses write: a Markdown report, CSV tables and their cells.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace facet::analysis {

// Sections in the order they were added, images and CSVs referenced by
// paths relative to the report.
class Report {
 public:
  void heading(const std::string& title);
  void paragraph(const std::string& text);
  void image(const std::string& relativePath, const std::string& caption);
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  void write(const std::filesystem::path& path, const std::string& title) const;  // atomically

 private:
  std::string markdown_;
};

// A CSV with a header row, written atomically; cells are written as given.
void writeCsv(const std::filesystem::path& path, const std::vector<std::string>& header,
              const std::vector<std::vector<std::string>>& rows);

// A number for a CSV cell or a table: shortest round-trip form.
std::string cell(double value);
// A number for a table in a printf format ("%.3g", "%+.2f%%"), at most 31 characters.
std::string formatted(const char* format, double value);

}  // namespace facet::analysis
