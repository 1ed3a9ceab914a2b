// SPDX-License-Identifier: Apache-2.0
#include "core/BandPipeline.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <climits>

namespace flarekit {

struct BandPipeline::State {
    int rows = 0, bandRows = 1, bands = 0;
    std::function<void(int, int)> work;
    //! Rows `work` may read; INT_MAX once cancelled, so a waiting helper wakes (an atomic
    //! wait returns only when the value has changed).
    std::atomic<int> published{0};
    std::atomic<int> next{0};  //!< the next band to claim
    std::atomic<bool> cancelled{false};
    std::unique_ptr<std::atomic<int>[]> done;  //!< per band: 1 once worked (or skipped)
    tbb::task_group helper;
    bool finished = false;

    //! Claims the next band, waits for its rows and works it; false when none is left. The
    //! caller's own thread passes `mayWait` false: it claims only a band whose rows are
    //! published, never one that would wait on the caller itself.
    bool workNext(bool mayWait) {
        int band = next.load();
        do {
            if (band >= bands) return false;
            if (!mayWait && std::min(rows, (band + 1) * bandRows) > published.load()) return false;
        } while (!next.compare_exchange_weak(band, band + 1));
        const int y0 = band * bandRows, y1 = std::min(rows, y0 + bandRows);
        for (int seen = published.load(); seen < y1; seen = published.load()) published.wait(seen);
        if (!cancelled.load()) work(y0, y1);
        done[band].store(1);
        done[band].notify_all();
        return true;
    }
};

BandPipeline::BandPipeline(int rows, int bandRows, std::function<void(int, int)> work, bool ready)
    : m(std::make_unique<State>()) {
    m->rows = std::max(0, rows);
    m->bandRows = std::max(1, bandRows);
    m->bands = (m->rows + m->bandRows - 1) / m->bandRows;
    m->work = std::move(work);
    m->published = ready ? m->rows : 0;
    m->done = std::make_unique<std::atomic<int>[]>(std::size_t(m->bands));
    for (int b = 0; b < m->bands; ++b) m->done[b].store(0);
    m->helper.run([state = m.get()] {
        while (state->workNext(true)) {
        }
    });
}

BandPipeline::~BandPipeline() {
    if (!m->finished) cancel();
    m->helper.wait();
}

void BandPipeline::publish(int rowEnd) {
    if (rowEnd <= m->published.load()) return;
    m->published.store(std::min(rowEnd, m->rows));
    m->published.notify_all();
}

void BandPipeline::waitFor(int rowEnd) {
    const int last = std::min(rowEnd, m->rows) - 1;
    for (int band = 0; last >= 0 && band <= last / m->bandRows; ++band) {
        while (m->done[band].load() == 0) {
            // Work a band rather than sit idle; when none is left, the helper holds this one.
            if (!m->workNext(false)) m->done[band].wait(0);
        }
    }
}

void BandPipeline::finish() {
    publish(m->rows);
    while (m->workNext(false)) {
    }
    m->helper.wait();  // the band the helper holds, or the helper itself if it never started
    m->finished = true;
}

void BandPipeline::cancel() {
    m->cancelled.store(true);
    m->published.store(INT_MAX);
    m->published.notify_all();
}

}  // namespace flarekit
