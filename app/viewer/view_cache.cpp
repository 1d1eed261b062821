#include "viewer/view_cache.h"

namespace isotrack::viewer {

bool ViewCache::needsRedraw(std::uint64_t signature, int width, int height) {
    if (!target_ || target_->width() != width || target_->height() != height) {
        target_.reset();  // free the old one first
        target_ = std::make_unique<render::OffscreenTarget>(width, height);
        valid_ = false;
    }
    const bool stale = !valid_ || signature != signature_;
    signature_ = signature;
    valid_ = true;
    return stale;
}

void ViewCache::present(int x, int y) const {
    if (target_) target_->blitToDefault(x, y);
}

}  // namespace isotrack::viewer
