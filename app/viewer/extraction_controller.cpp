#include "viewer/extraction_controller.h"

namespace isotrack::viewer {

void ExtractionController::setSource(VolumeSource source) {
    if (source != source_) confirmed_.clear();
    source_ = std::move(source);
    iso_.reset();
}

void ExtractionController::submit(std::vector<PreviousSurface> surfaces, bool onlyOwnIsovalues) {
    ExtractionRequest request;
    request.generation = ++generation_;
    request.source = source_;
    request.iso = iso_;
    request.table = table_;
    request.method = method_;
    request.minPersistence = minPersistence_;
    request.confirmed = confirmed(method_);
    if (!lastRequest_ || supersedes(request, *lastRequest_)) epoch_ = request.generation;
    lastRequest_ = request;
    request.surfaces = std::move(surfaces);
    request.onlyOwnIsovalues = onlyOwnIsovalues;
    worker_.submit(std::move(request));
}

std::optional<ExtractionResult> ExtractionController::take() {
    std::optional<ExtractionResult> result = worker_.poll();
    if (result && result->generation < epoch_) result.reset();
    return result;
}

void ExtractionController::applied(const ExtractionResult& result) {
    shownIso_ = result.iso;
    lastMs_ = result.extractMs;
    ++applied_;
}

}  // namespace isotrack::viewer
