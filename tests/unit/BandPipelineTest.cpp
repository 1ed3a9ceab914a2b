// SPDX-License-Identifier: Apache-2.0
// BandPipeline: every band worked exactly once, never before its rows are published, finished
// on one thread as on two, and nothing left running after a cancel.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "core/BandPipeline.h"
#include "core/Parallel.h"

using namespace flarekit;

namespace {

//! Per row: how many times it was worked, and the rows published when it was.
struct Record {
    std::vector<std::atomic<int>> times;
    std::vector<int> publishedThen;
    explicit Record(int rows) : times(std::size_t(rows)), publishedThen(std::size_t(rows), -1) {}
};

}  // namespace

TEST(BandPipeline, BeforeAConsumerEveryRowIsWorkedOnceAndBeforeItIsRead) {
    for (const int threads : {1, 2}) {
        ThreadLimit limit(threads);
        for (const int rows : {0, 1, 16, 17, 1080}) {
            Record record(rows);
            std::vector<int> row(std::size_t(rows), 0);
            {
                BandPipeline pipeline(
                    rows, 16,
                    [&](int y0, int y1) {
                        for (int y = y0; y < y1; ++y) {
                            ++record.times[std::size_t(y)];
                            row[std::size_t(y)] = y + 1;
                        }
                    },
                    true);
                for (int y = 0; y < rows; y += 7) {  // a consumer reading in its own steps
                    const int end = std::min(rows, y + 7);
                    pipeline.waitFor(end);
                    for (int r = y; r < end; ++r) ASSERT_EQ(row[std::size_t(r)], r + 1);
                }
            }
            for (int y = 0; y < rows; ++y)
                EXPECT_EQ(record.times[std::size_t(y)].load(), 1) << threads << " " << y;
        }
    }
}

TEST(BandPipeline, AfterAProducerOnlyPublishedRowsAreWorked) {
    for (const int threads : {1, 2}) {
        ThreadLimit limit(threads);
        const int rows = 500;
        Record record(rows);
        std::atomic<int> published{0};
        BandPipeline pipeline(
            rows, 16,
            [&](int y0, int y1) {
                for (int y = y0; y < y1; ++y) {
                    ++record.times[std::size_t(y)];
                    record.publishedThen[std::size_t(y)] = published.load();
                }
            },
            false);
        for (int y = 0; y < rows; y += 5) {  // a decoder finishing 5 rows at a time
            std::this_thread::yield();
            published = std::min(rows, y + 5);
            pipeline.publish(published);
        }
        pipeline.finish();
        for (int y = 0; y < rows; ++y) {
            EXPECT_EQ(record.times[std::size_t(y)].load(), 1) << threads << " " << y;
            // The band of row y ends at a multiple of 16 (or the last row): all published.
            EXPECT_GE(record.publishedThen[std::size_t(y)], std::min(rows, (y / 16 + 1) * 16))
                << threads << " " << y;
        }
    }
}

TEST(BandPipeline, ACancelledPipelineWorksNoUnpublishedRow) {
    std::atomic<int> worked{0};
    std::atomic<int> beyond{0};
    {
        BandPipeline pipeline(
            1000, 10,
            [&](int y0, int y1) {
                worked += y1 - y0;
                if (y1 > 100) ++beyond;
            },
            false);
        pipeline.publish(100);
        // The helper may be working a published band; it must not touch a later one.
        for (int i = 0; i < 100 && worked.load() < 100; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        pipeline.cancel();
    }  // the destructor waits for the helper
    EXPECT_EQ(beyond.load(), 0);
    EXPECT_LE(worked.load(), 100);
}
