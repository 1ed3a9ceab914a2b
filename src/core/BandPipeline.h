// SPDX-License-Identifier: Apache-2.0
// Two serial stages over an image's rows, overlapped on two cores: a codec's own pass (libpng
// decoding or deflating rows, one thread by its design) and flarekit's conversion of the same
// rows (sRGB decode to float, or encode from float). Run one after the other they add up; run
// band by band on a helper task, the conversion hides behind the codec.
#pragma once

#include <atomic>
#include <functional>
#include <memory>

namespace flarekit {

//! Runs `work(y0, y1)` once for every band of `bandRows` rows of `rows`, in order, on a helper
//! task of the thread pool; the caller claims bands too whenever it would otherwise wait, so
//! the pipeline finishes on one thread as well (a pool limited to one thread, the demo's
//! writer). Two uses:
//! - after a producer: `work` reads rows the caller publishes (a decoder's output) and runs
//!   only on published rows; the caller publishes as it goes (waiting with waitFor for rows
//!   whose room it reuses) and calls finish() at the end;
//! - before a consumer: `work` reads nothing the caller makes (`ready` true: every row is
//!   published at once) and the caller calls waitFor(rowEnd) before it reads a band.
//! The destructor cancels what has not started and waits for the helper: nothing outlives it.
class BandPipeline {
  public:
    BandPipeline(int rows, int bandRows, std::function<void(int, int)> work, bool ready);
    ~BandPipeline();
    BandPipeline(const BandPipeline&) = delete;
    BandPipeline& operator=(const BandPipeline&) = delete;

    //! Rows [0, rowEnd) may now be read by `work`.
    void publish(int rowEnd);
    //! Returns once rows [0, rowEnd) have been worked, working unclaimed published bands
    //! meanwhile.
    void waitFor(int rowEnd);
    //! Publishes every row and returns once every band has been worked.
    void finish();
    //! Bands not yet started are skipped (the caller stopped: a decode error).
    void cancel();

    struct State;

  private:
    std::unique_ptr<State> m;
};

}  // namespace flarekit
