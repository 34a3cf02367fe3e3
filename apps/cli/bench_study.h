#pragma once
/// `f2 bench --study`: the design document's tables 4.1 and 4.2, frames per
/// second against the number of robots and of spheres, as Markdown, CSV and a
/// gnuplot PNG.
#include <string>
#include <vector>

#include "bench_measure.h"
#include "bench_peer.h"

namespace f2::cli {

struct StudySettings {
    BenchSettings bench;  ///< per point; the study defaults to 1 s a point
    int width = 800, height = 600;
    std::vector<int> counts = {1, 10, 100, 1000, 10000, 100000};
    std::string csvOut = "bench_study.csv";
    std::string plotOut = "bench_study.png";  ///< empty = no plot
    /// The Embree peer on the same frames, when given: its columns in the
    /// tables and CSV, its lines in the plot.
    std::optional<PeerSettings> peer;
};

/// Measures every point (progress on stderr), prints the tables on stdout,
/// writes the CSV and the plot. Returns the exit code.
int runStudy(const StudySettings& settings);

}  // namespace f2::cli
