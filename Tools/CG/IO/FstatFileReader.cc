#include "IO/FstatFileReader.h"

#include <cmath>

#include "Formats/FstatFormat.h"
#include "IO/InputError.h"

namespace talus::cg {

namespace column = formats::fstat;  // the contact columns

namespace {

bool isHeader(std::string_view line) {
    const auto first = line.find_first_not_of(" \t");
    return first != std::string_view::npos && line[first] == '#';
}
}  // namespace

FstatFileReader::FstatFileReader(const std::string& path) : file_(path) {}

bool FstatFileReader::readFrame(ContactFrame& frame, std::size_t expectedLines) {
    do {
        if (!file_.nextLine(line_)) return false;
        splitFields(line_, fields_);
    } while (fields_.empty());
    if (!isHeader(line_)) {
        file_.fail("expected a frame header '# t 1', found a line starting with '" +
                   std::string(fields_[0]) + "'");
    }
    // "# t marker" (the '#' may stand alone or touch the time).
    std::vector<std::string_view> values(fields_.begin(), fields_.end());
    if (values[0] == "#") values.erase(values.begin());
    else values[0].remove_prefix(1);
    if (values.size() != 2) {
        file_.fail("expected the frame header '# t 1' (time and format marker), found " +
                   std::to_string(values.size()) + " fields after '#'");
    }
    frame.time = parseReal(values[0], file_, "the frame time");
    frame.headerLine = file_.lineNumber();
    const long marker = parseInteger(values[1], file_, "the format marker");
    if (marker != column::contactPointMarker) {
        file_.fail("format marker " + std::to_string(marker) +
                   ": only marker 1 (columns 4-6 hold the contact point) is supported");
    }
    for (int h = 1; h < column::headerLines; ++h) {
        if (!file_.nextLine(line_)) {
            file_.failAtLine(file_.lineNumber() + 1, "file ends inside the header of the frame at t = " +
                                                         str(frame.time) + ": truncated file?");
        }
        if (!isHeader(line_))
            file_.fail("expected header line " + std::to_string(h + 1) + " of " + std::to_string(column::headerLines) +
                       " starting with '#'");
    }
    frame.contacts.clear();
    frame.contacts.reserve(expectedLines);
    while (file_.nextLine(line_)) {
        splitFields(line_, fields_);
        if (fields_.empty()) continue;
        if (isHeader(line_)) {
            file_.pushBack();
            break;
        }
        if (fields_.size() != column::columns) {
            file_.fail("expected " + std::to_string(column::columns) + " columns, found " +
                       std::to_string(fields_.size()));
        }
        const double t = parseReal(fields_[column::time], file_, "the time");
        if (std::abs(t - frame.time) > 1e-9 * std::max(1.0, std::abs(frame.time))) {
            file_.fail("contact time " + str(t) + " differs from the frame time " + str(frame.time) +
                       " (header line " + std::to_string(frame.headerLine) + ")");
        }
        ContactLine c;
        c.i = parseInteger(fields_[column::particle], file_, "particle i");
        c.j = parseInteger(fields_[column::partner], file_, "partner j");
        if (c.i < 0) file_.fail("particle index i must not be negative, found " + std::to_string(c.i));
        Vec3 t_{};
        for (int k = 0; k < 3; ++k) {
            c.point[k] = parseReal(fields_[column::contactPoint + k], file_, "the contact point");
            c.normal[k] = parseReal(fields_[column::normal + k], file_, "the normal");
            t_[k] = parseReal(fields_[column::tangent + k], file_, "the tangential direction");
        }
        c.overlap = parseReal(fields_[column::overlap], file_, "the overlap dn");
        const double fn = parseReal(fields_[column::normalForce], file_, "the normal force fn");
        const double ft = parseReal(fields_[column::tangentialForce], file_, "the tangential force");
        // fstat.md: force on i = fn n + ft t for pairs; walls flip both vectors.
        const double sign = c.isWall() ? -1.0 : 1.0;
        for (int k = 0; k < 3; ++k) c.force[k] = sign * (fn * c.normal[k] + ft * t_[k]);
        c.line = file_.lineNumber();
        frame.contacts.push_back(c);
    }
    return true;
}

std::vector<ContactFrame> readAllFstatFrames(const std::string& path) {
    FstatFileReader reader(path);
    std::vector<ContactFrame> frames;
    ContactFrame frame;
    while (reader.readFrame(frame)) frames.push_back(frame);
    if (frames.empty()) throw InputError(path + ": no frames (empty .fstat file)");
    return frames;
}

}  // namespace talus::cg
