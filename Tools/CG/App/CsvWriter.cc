#include "App/CsvWriter.h"

#include <charconv>

#include "IO/InputError.h"

namespace talus::cg {

CsvWriter::CsvWriter(const std::string& path, const Coordinates& coordinates, bool withTime,
                     const std::vector<OutputColumn>& fields, const std::vector<std::string>& comments)
    : CsvWriter(path, coordinates.kernelAxes(), withTime, fields, comments, &coordinates) {}

CsvWriter::CsvWriter(const std::string& path, const std::vector<int>& axes, bool withTime,
                     const std::vector<OutputColumn>& fields, const std::vector<std::string>& comments,
                     const Coordinates* coordinates)
    : path_(path), file_(std::fopen(path.c_str(), "w")), axes_(axes), withTime_(withTime) {
    if (file_ == nullptr) throw InputError("-o: cannot write " + path);
    for (const std::string& line : comments) std::fprintf(file_, "# %s\n", line.c_str());
    std::string units = "# units (M mass, L length, T time):";
    std::string names;
    auto add = [&](const std::string& name, const std::string& unit) {
        units += " " + name + " [" + unit + "]";
        if (!names.empty()) names += ',';
        names += name;
    };
    if (withTime) add("t", "T");
    for (int k : axes_) add(coordinates ? coordinates->coordinateName(k) : std::string(1, axisLetter(k)), "L");
    for (const OutputColumn& c : fields) add(c.name, c.unit);
    std::fprintf(file_, "%s\n%s\n", units.c_str(), names.c_str());
}

CsvWriter::~CsvWriter() {
    if (file_ != nullptr) std::fclose(file_);
}

// Each number as printf's %.12g writes it (std::to_chars with a precision is specified to give
// the same characters), a row at a time: fprintf per number was a third of the cost of a
// sampled profile written at every sample during a run.
void CsvWriter::writeRow(double time, const Vec3& point, const std::vector<double>& values) {
    row_.clear();
    auto put = [&](double v) {
        char number[32];
        const std::to_chars_result end = std::to_chars(number, number + sizeof number, v, std::chars_format::general, 12);
        if (!row_.empty()) row_ += ',';
        row_.append(number, end.ptr);
    };
    if (withTime_) put(time);
    for (int k : axes_) put(point[k]);
    for (double v : values) put(v);
    row_ += '\n';
    std::fwrite(row_.data(), 1, row_.size(), file_);
}

void CsvWriter::close() {
    if (file_ == nullptr) return;
    const bool failed = std::ferror(file_) != 0;
    const bool closeFailed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (failed || closeFailed) throw InputError("-o: writing " + path_ + " failed (disk full?)");
}

}  // namespace talus::cg
