#include "bench_study.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace f2::cli {

namespace {

struct StudyPoint {
    BenchShape shape;
    int count;
    BenchResult result;
    std::optional<PeerResult> peer;
};

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

const char* shapeName(BenchShape shape) {
    return shape == BenchShape::Robots ? "robots" : shape == BenchShape::Spheres ? "spheres" : "lamps";
}

void printTable(std::ostream& out, const std::string& title, const char* column, BenchShape shape,
                const std::vector<StudyPoint>& points, bool withPeer) {
    // Lamps: each lamp is a light, so the trace time per light is the figure to watch.
    const bool perLight = shape == BenchShape::Lamps;
    out << "\n### " << title << "\n\n"
        << "| " << column
        << " | Primitives | FPS | Frame, ms (median) | min..max, ms | Evaluate, ms | Build, ms "
        << "| Trace, ms | Mrays/s | Peak RSS, MB |" << (perLight ? " Lights | Trace per light, ms |" : "")
        << (withPeer ? " Embree peer FPS (mode) | f2 / peer |" : "")
        << "\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" << (perLight ? "---:|---:|" : "")
        << (withPeer ? "---:|---:|" : "") << "\n";
    for (const StudyPoint& p : points) {
        if (p.shape != shape) continue;
        const BenchResult& r = p.result;
        out << "| " << p.count << " | " << r.primitives << " | " << fixed(r.fps(), 1) << " | "
            << fixed(r.msMedian, 2) << " | " << fixed(r.msMin, 2) << ".." << fixed(r.msMax, 2) << " | "
            << fixed(r.msEval, 2) << " | " << fixed(r.msBuild, 2) << " | " << fixed(r.msTrace, 2) << " | "
            << fixed(r.mraysPerSecond(), 1) << " | " << fixed(r.peakRssMb, 1) << " |";
        if (perLight) out << ' ' << r.lights << " | " << fixed(r.msTracePerLight(), 3) << " |";
        if (withPeer && p.peer)
            out << ' ' << fixed(p.peer->fps, 1) << " (" << p.peer->mode << ") | "
                << fixed(r.fps() / p.peer->fps, 2) << " |";
        out << '\n';
    }
}

bool writeCsv(const std::string& path, const std::vector<StudyPoint>& points) {
    std::ofstream csv(path);
    csv << "shape,count,primitives,width,height,threads,frame,frames,fps,ms_median,ms_min,ms_max,ms_p10,ms_"
           "p90,"
           "ms_eval,ms_build,ms_trace,primary_rays,shadow_rays,mrays_per_s,peak_rss_mb,lights,peer_fps,peer_"
           "mode\n";
    for (const StudyPoint& p : points) {
        const BenchResult& r = p.result;
        csv << shapeName(p.shape) << ',' << p.count << ',' << r.primitives << ',' << r.width << ','
            << r.height << ',' << r.threads << ',' << r.frame << ',' << r.frames << ',' << fixed(r.fps(), 3)
            << ',' << fixed(r.msMedian, 4) << ',' << fixed(r.msMin, 4) << ',' << fixed(r.msMax, 4) << ','
            << fixed(r.msP10, 4) << ',' << fixed(r.msP90, 4) << ',' << fixed(r.msEval, 4) << ','
            << fixed(r.msBuild, 4) << ',' << fixed(r.msTrace, 4) << ',' << r.rays.primary << ','
            << r.rays.shadow << ',' << fixed(r.mraysPerSecond(), 3) << ',' << fixed(r.peakRssMb, 2) << ','
            << r.lights << ',' << (p.peer ? fixed(p.peer->fps, 3) : "") << ',' << (p.peer ? p.peer->mode : "")
            << '\n';
    }
    csv.flush();
    return bool(csv);
}

/// A gnuplot single-quoted string: only the quote itself needs doubling.
std::string gnuplotQuoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

/// Whether this gnuplot has the cairo PNG terminal (nicer text); else plain `png`.
bool hasPngCairo() {
    FILE* pipe = popen("gnuplot -e 'set terminal' 2>&1", "r");
    if (!pipe) return false;
    std::string text;
    char buf[512];
    while (std::fgets(buf, sizeof buf, pipe)) text += buf;
    pclose(pipe);
    return text.find("pngcairo") != std::string::npos;
}

bool writePlot(const std::string& path, const std::vector<StudyPoint>& points,
               const StudySettings& settings) {
    const BenchResult& any = points.front().result;
    std::ostringstream script;
    script << "set terminal " << (hasPngCairo() ? "pngcairo size 900,600" : "png size 900,600") << '\n'
           << "set output " << gnuplotQuoted(path) << '\n'
           << "set title "
           << gnuplotQuoted(std::string(settings.peer ? "f2 and the Embree peer" : "f2 bench --study") +
                            ": whole frame (evaluate + build + trace), " + std::to_string(any.width) + "x" +
                            std::to_string(any.height) + ", " + std::to_string(any.threads) + " threads")
           << '\n'
           << "set logscale xy\nset xlabel 'N (robots, spheres or lamps)'\nset ylabel 'frames per second "
              "(median)'\n"
           << "set grid\nset key bottom left\n";
    bool withPeer = false;
    for (BenchShape shape : {BenchShape::Robots, BenchShape::Spheres, BenchShape::Lamps}) {
        // Columns: N, f2 FPS, peer FPS ("NaN" where the peer did not run: gnuplot leaves a gap).
        script << '$' << shapeName(shape) << " << EOD\n";
        for (const StudyPoint& p : points) {
            if (p.shape != shape) continue;
            script << p.count << ' ' << fixed(p.result.fps(), 3) << ' '
                   << (p.peer ? fixed(p.peer->fps, 3) : std::string("NaN")) << '\n';
            withPeer = withPeer || p.peer;
        }
        script << "EOD\n";
    }
    script << "plot $robots using 1:2 with linespoints lw 2 pt 7 lc 1 title 'f2, robots (table 4.1)', "
              "$spheres using 1:2 with linespoints lw 2 pt 5 lc 2 title 'f2, spheres (table 4.2)'";
    if (std::any_of(points.begin(), points.end(),
                    [](const StudyPoint& p) { return p.shape == BenchShape::Lamps; }))
        script << ", $lamps using 1:2 with linespoints lw 2 pt 9 lc 3 title 'f2, lamps, a light each (table "
                  "4.3)'";
    if (withPeer)
        script << ", $robots using 1:3 with linespoints lw 2 dt 2 pt 6 lc 1 title 'Embree peer, robots', "
                  "$spheres using 1:3 with linespoints lw 2 dt 2 pt 4 lc 2 title 'Embree peer, spheres'";
    script << '\n';
    FILE* pipe = popen("gnuplot", "w");
    if (!pipe) return false;
    std::string text = script.str();
    bool written = std::fwrite(text.data(), 1, text.size(), pipe) == text.size();
    return pclose(pipe) == 0 && written;
}

}  // namespace

int runStudy(const StudySettings& settings) {
    std::vector<StudyPoint> points;
    for (BenchShape shape : {BenchShape::Robots, BenchShape::Spheres, BenchShape::Lamps}) {
        for (int count : settings.counts) {
            if (count > benchMaxCount(shape)) continue;  // lamps: at most 1,000 (a light each)
            BenchSceneSpec spec{shape, count};
            auto loaded = loadBenchScene(spec, settings.width, settings.height);
            if (!loaded) return 1;
            resetPeakRss();  // each point's own peak, as far as the kernel allows
            const CameraDesc& camera = loaded->scene.camera;
            BenchResult result =
                runBench(loaded->scene, loaded->name, camera.width, camera.height, settings.bench);
            std::cerr << "f2 bench --study: " << result.scene << ": " << fixed(result.fps(), 1) << " FPS ("
                      << fixed(result.msMedian, 2) << " ms, " << result.frames << " frames)\n";
            std::optional<PeerResult> peer;
            if (settings.peer && shape != BenchShape::Lamps) {  // the Embree peer has directional lights only
                // After f2's measurement, so that the exported text is not part of f2's peak RSS.
                std::string error;
                peer = runPeer(*settings.peer, loaded->scene, settings.bench.frame,
                               cameraAt(loaded->scene, settings.bench.frame), loaded->name, error);
                if (!peer) {
                    std::cerr << "f2 bench: Embree peer: " << error << '\n';
                    return 1;
                }
                std::cerr << "f2 bench --study: " << result.scene << ": Embree peer " << fixed(peer->fps, 1)
                          << " FPS (--rebuild " << peer->mode << ")\n";
            }
            points.push_back({shape, count, std::move(result), peer});
        }
    }
    const BenchResult& first = points.front().result;
    std::cout << "## f2 bench --study: FPS against the number of objects\n\n"
              << "Whole frame (evaluate + build + trace + shade), " << first.width << "x" << first.height
              << ", shadows on, " << first.threads << " threads, frame " << first.frame
              << ", median of >= " << settings.bench.seconds << " s per point.\n";
    const bool withPeer = settings.peer.has_value();
    if (withPeer)
        std::cout << "Embree peer: " << settings.peer->program
                  << " on the same frames (`f2 export --prims`), "
                  << "whole frame, best of --rebuild";
    if (withPeer)
        for (const std::string& mode : settings.peer->modes) std::cout << ' ' << mode;
    if (withPeer) std::cout << ".\n";
    printTable(std::cout, "Table 4.1. Frame rate with robots (robots:N)", "Robots", BenchShape::Robots,
               points, withPeer);
    printTable(std::cout, "Table 4.2. Frame rate with spheres (spheres:N)", "Spheres", BenchShape::Spheres,
               points, withPeer);
    printTable(std::cout, "Table 4.3. Frame rate with lamps, a point light each (lamps:N, N <= 1000)",
               "Lamps", BenchShape::Lamps, points, withPeer);

    int code = 0;
    if (!writeCsv(settings.csvOut, points)) {
        std::cerr << "f2 bench: cannot write " << settings.csvOut << '\n';
        code = 1;
    } else {
        std::cerr << "f2 bench: wrote " << settings.csvOut << '\n';
    }
    if (!settings.plotOut.empty()) {
        if (writePlot(settings.plotOut, points, settings)) {
            std::cerr << "f2 bench: wrote " << settings.plotOut << '\n';
        } else {
            std::cerr << "f2 bench: gnuplot could not write " << settings.plotOut
                      << " (is gnuplot installed? the tables and CSV are complete)\n";
            code = 1;
        }
    }
    return code;
}

}  // namespace f2::cli
