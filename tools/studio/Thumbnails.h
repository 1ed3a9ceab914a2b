// SPDX-License-Identifier: Apache-2.0
// The preset browser's thumbnails: every shipped sprite preset rendered on the current image
// (small) with the current light, on a thread of its own so that the window never waits for
// them. A new request makes the old one stale: its remaining presets are skipped and its
// results dropped. The worker runs the library's parallel loops on its own thread only
// (runOnThisThread), so it never takes the cores the view's update runs on.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "Document.h"
#include "flarekit/Image.h"

namespace flarekit::studio {

struct Thumbnail {
    std::string preset;
    Image8 image;       //!< empty when the preset could not be rendered
    std::string error;  //!< why not
    unsigned generation = 0;
};

class ThumbnailRenderer {
  public:
    ThumbnailRenderer();
    ~ThumbnailRenderer();
    ThumbnailRenderer(const ThumbnailRenderer&) = delete;
    ThumbnailRenderer& operator=(const ThumbnailRenderer&) = delete;

    //! Renders `presets` on `image` (already small) with the light at `light` (its pixels),
    //! through `view`; returns at once. Earlier requests become stale.
    void request(FlareKind kind, PixelInput image, Point light, ViewSettings view,
                 std::vector<std::string> presets);
    //! The thumbnails finished since the last call, of the newest request only.
    std::vector<Thumbnail> take();
    //! True while the newest request still has presets to render.
    bool busy() const;
    unsigned generation() const;

  private:
    void work();
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
    unsigned m_generation = 0;
    FlareKind m_kind = FlareKind::Sprite;
    PixelInput m_image;
    Point m_light;
    ViewSettings m_view;
    std::deque<std::string> m_queue;
    bool m_working = false;
    std::vector<Thumbnail> m_done;
    std::thread m_thread;  //!< last: starts after every member it reads exists
};

}  // namespace flarekit::studio
