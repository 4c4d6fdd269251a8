#include "App/FieldWriter.h"

#include "App/CsvWriter.h"
#include "App/StatFieldWriter.h"
#include "App/VtkFieldWriter.h"
#include "Fields/DerivedFields.h"
#include "IO/InputError.h"
#ifdef TALUS_CG_WITH_HDF5
#include "App/Hdf5FieldWriter.h"
#endif

namespace talus::cg {

namespace {

// The CSV file: one row per point (and per frame without time averaging) of derived fields.
class CsvFieldWriter : public FieldWriter {
public:
    explicit CsvFieldWriter(const FieldOutputSetup& setup)
        : setup_(setup), csv_(setup.path, setup.coordinates, !setup.timeAverage, derivedColumns(setup.layout), setup.comments) {}
    void writeFrame(double, double time, const std::vector<double>& sums) override {
        std::vector<double> values;
        for (std::size_t p = 0; p < setup_.points.size(); ++p) {
            values.clear();
            appendDerivedFields(setup_.layout, sums.data() + p * setup_.layout.count(), values);
            csv_.writeRow(time, setup_.points[p], values);
        }
    }
    void close() override { csv_.close(); }

private:
    FieldOutputSetup setup_;
    CsvWriter csv_;
};

}  // namespace

OutputFormat outputFormatFromName(const std::string& name) {
    if (name == "csv") return OutputFormat::Csv;
    if (name == "hdf5" || name == "h5") return OutputFormat::Hdf5;
    if (name == "stat") return OutputFormat::Stat;
    if (name == "vtk") return OutputFormat::Vtk;
    throw InputError("--output-format: unknown format '" + name + "' (csv, hdf5, stat or vtk)");
}

std::string defaultOutputPath(OutputFormat format, const std::string& base) {
    switch (format) {
        case OutputFormat::Hdf5: return base + ".cg.h5";
        case OutputFormat::Stat: return base + ".stat";
        case OutputFormat::Vtk: return base + ".cg.pvd";
        case OutputFormat::Csv: break;
    }
    return base + ".cg.csv";
}

bool hdf5Available() {
#ifdef TALUS_CG_WITH_HDF5
    return true;
#else
    return false;
#endif
}

void requireOutputFormatAvailable(OutputFormat format) {
    if (format == OutputFormat::Hdf5 && !hdf5Available()) {
        throw InputError("--output-format hdf5: this talus-cg was built without HDF5 (install libhdf5-dev and "
                         "configure with -DTALUS_WITH_HDF5=ON); use csv or stat");
    }
}

std::unique_ptr<FieldWriter> makeFieldWriter(OutputFormat format, const FieldOutputSetup& setup) {
    requireOutputFormatAvailable(format);
    switch (format) {
        case OutputFormat::Stat: return std::make_unique<StatFieldWriter>(setup);
        case OutputFormat::Vtk: return std::make_unique<VtkFieldWriter>(setup);
        case OutputFormat::Hdf5:
#ifdef TALUS_CG_WITH_HDF5
            return std::make_unique<Hdf5FieldWriter>(setup);
#else
            break;
#endif
        case OutputFormat::Csv: break;
    }
    return std::make_unique<CsvFieldWriter>(setup);
}

}  // namespace talus::cg
