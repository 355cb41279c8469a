// SPDX-License-Identifier: MIT
// How library code that owns no threads (mesh building) is lent some by
// code that does (the renderer's pool): a ParallelFor calls job(i) once for
// each i in [0, count), on any of its threads and in any order, and returns
// when all are done, rethrowing the first exception a job threw. An empty
// one means the calling thread, in order. Whatever runs the jobs, the
// results must be the same bit for bit: jobs write apart, and whatever
// depends on order is left to the caller.
#pragma once

#include <cstddef>
#include <functional>

namespace litkit {

using ParallelJob = std::function<void(std::size_t index)>;
using ParallelFor = std::function<void(std::size_t count, const ParallelJob& job)>;

inline void run_parallel(const ParallelFor& parallel, std::size_t count, const ParallelJob& job) {
    if (parallel) {
        parallel(count, job);
    } else {
        for (std::size_t index = 0; index < count; ++index) job(index);
    }
}

// Jobs of `chunk` consecutive indices each, for loops over many small items.
template <class Body>
void parallel_chunks(const ParallelFor& parallel, std::size_t count, std::size_t chunk,
                     Body&& body) {
    run_parallel(parallel, (count + chunk - 1) / chunk, [&](std::size_t c) {
        const std::size_t end = count - c * chunk < chunk ? count : c * chunk + chunk;
        for (std::size_t i = c * chunk; i < end; ++i) body(i);
    });
}

}  // namespace litkit
