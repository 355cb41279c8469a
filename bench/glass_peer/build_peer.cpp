// SPDX-License-Identifier: MIT
// litkit_build_peer: the tracer's hierarchy built over the 261,120-triangle
// sphere (make_sphere(1, 512, 256), as BM_TraceBuild261k) by litkit
// (trace::Accel, on T threads lent from a ThreadPool) and by Intel Embree
// (rtcCommitScene of one triangle geometry on a device of T threads, at
// Embree's default build quality, its binned SAH), in one run, the side
// going first alternating from round to round. Each side's build runs in
// the same process over the same mesh; what is timed is the build alone
// (Embree's device and geometry are made before the clock starts).
//
//   litkit_build_peer [--threads T] [--rounds R]
//   litkit_build_peer --once
//
// Prints both sides' smallest and median times over the rounds and their
// ratio (Embree / litkit: above 1, litkit's build is the faster). --once
// builds litkit's hierarchy once on the calling thread and nothing else,
// for counting its instructions (valgrind --tool=callgrind).
#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/thread_pool.hpp"
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"
#include "trace/accel.hpp"

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 2, rounds = 15;
    bool once = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--once") == 0) {
            once = true;
        } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
            threads = std::atoi(argv[++i]);
        } else if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc) {
            rounds = std::atoi(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: %s [--threads T] [--rounds R] | --once\n", argv[0]);
            return 2;
        }
    }
    if (threads < 1 || rounds < 1) {
        std::fprintf(stderr, "threads and rounds must be at least 1\n");
        return 2;
    }
    const litkit::Mesh mesh = litkit::make_sphere(1.0f, 512, 256);
    const std::vector<litkit::trace::MeshView> objects{{mesh.positions, mesh.triangles}};
    if (once) {
        const litkit::trace::Accel accel(objects);
        return accel.nearest_front({{0.0f, 0.0f, 3.0f}, {0, 0, -1}}).found() ? 0 : 1;
    }
    litkit::ThreadPool pool(threads);
    const litkit::ParallelFor lent =
        threads > 1
            ? litkit::ParallelFor([&pool](std::size_t count, const litkit::ParallelJob& job) {
                  pool.parallel_for(count, [&](std::size_t i, int) { job(i); });
              })
            : litkit::ParallelFor{};
    const std::string config = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    if (device == nullptr) {
        std::fprintf(stderr, "Embree: no device (%s)\n", config.c_str());
        return 1;
    }

    const auto run_litkit = [&] {
        const auto start = std::chrono::steady_clock::now();
        const litkit::trace::Accel accel(objects, lent);
        const double ms = milliseconds_since(start);
        // The hierarchy answers: one ray through the sphere's centre.
        const litkit::trace::Hit hit = accel.nearest_front({{0.0f, 0.0f, 3.0f}, {0, 0, -1}});
        if (!hit.found() || std::abs(hit.t - 2.0f) > 1e-3f) std::abort();
        return ms;
    };
    const auto run_embree = [&] {
        RTCScene scene = rtcNewScene(device);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                   mesh.positions.data(), 0, sizeof(mesh.positions[0]),
                                   mesh.positions.size());
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                   mesh.triangles.data(), 0, sizeof(mesh.triangles[0]),
                                   mesh.triangles.size());
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene, geometry);
        rtcReleaseGeometry(geometry);
        const auto start = std::chrono::steady_clock::now();
        rtcCommitScene(scene);
        const double ms = milliseconds_since(start);
        RTCBounds bounds;
        rtcGetSceneBounds(scene, &bounds);
        if (!(bounds.upper_x > 0.99f && bounds.upper_x < 1.01f)) std::abort();
        rtcReleaseScene(scene);
        return ms;
    };
    run_litkit(), run_embree();  // warm-up: threads started, pages mapped
    std::vector<double> ours, theirs;
    for (int round = 0; round < rounds; ++round) {
        if (round % 2 == 0) {
            ours.push_back(run_litkit()), theirs.push_back(run_embree());
        } else {
            theirs.push_back(run_embree()), ours.push_back(run_litkit());
        }
    }
    rtcReleaseDevice(device);
    const double our_min = *std::min_element(ours.begin(), ours.end());
    const double their_min = *std::min_element(theirs.begin(), theirs.end());
    std::printf("261,120 triangles, %d thread(s), %d rounds\n", threads, rounds);
    std::printf("litkit  (trace::Accel)     smallest %6.1f ms  median %6.1f ms\n", our_min,
                median(ours));
    std::printf("Embree  (rtcCommitScene)   smallest %6.1f ms  median %6.1f ms\n", their_min,
                median(theirs));
    std::printf("Embree / litkit: %.2f (smallest), %.2f (median)\n", their_min / our_min,
                median(theirs) / median(ours));
    return 0;
}
