// A CSV file written row by row and flushed after each, so a long study stopped with Ctrl-C
// keeps every row it measured.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace weft::bench {

class CsvFile {
  public:
    CsvFile(const std::string& path, const std::vector<std::string>& header) {
        file_ = std::fopen(path.c_str(), "w");
        if (file_) write_row(header);
    }
    ~CsvFile() {
        if (file_) std::fclose(file_);
    }
    CsvFile(const CsvFile&) = delete;
    CsvFile& operator=(const CsvFile&) = delete;

    bool is_open() const { return file_ != nullptr; }

    void write_row(const std::vector<std::string>& cells) {
        for (std::size_t c = 0; c < cells.size(); ++c)
            std::fprintf(file_, "%s%s", c ? "," : "", cells[c].c_str());
        std::fprintf(file_, "\n");
        std::fflush(file_);
    }

  private:
    std::FILE* file_ = nullptr;
};

// Shortest text that round-trips the double (or "nan", "inf").
inline std::string cell(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

}  // namespace weft::bench
