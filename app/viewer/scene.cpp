#include "viewer/scene.h"

#include <algorithm>

#include "render/pick_target.h"
#include "render/snapshot.h"
#include "viewer/signature.h"

namespace isotrack::viewer {

bool Scene::setVolume(std::shared_ptr<const LoadedVolume> volume) {
    const bool changed = volume_ != volume;
    volume_ = std::move(volume);
    return changed;
}

render::Bounds Scene::volumeBounds() const {
    if (!volume_) return render::Bounds{glm::vec3(0.0f), glm::vec3(1.0f)};
    return render::volumeBounds(volume_->volume);
}

render::Bounds Scene::drawBounds() const {
    std::vector<glm::vec3> offsets;
    for (const auto& surface : surfaces_) {
        if (surface->style().visible && surface->offset() != glm::vec3(0.0f)) offsets.push_back(surface->offset());
    }
    return render::boundsWithOffsets(volumeBounds(), offsets);
}

SurfaceStructure* Scene::find(std::uint32_t id) {
    for (auto& surface : surfaces_) {
        if (surface->id() == id) return surface.get();
    }
    return nullptr;
}

const SurfaceStructure* Scene::find(std::uint32_t id) const { return const_cast<Scene*>(this)->find(id); }

const SurfaceStructure* Scene::findByPickId(std::uint32_t pickId) const {
    return pickId == 0 ? nullptr : find(pickId - 1);
}

void Scene::add(std::unique_ptr<SurfaceStructure> surface) {
    surface->setExplode(explode_, volumeCentre());
    surfaces_.push_back(std::move(surface));
}

void Scene::remove(std::uint32_t id) {
    surfaces_.erase(std::remove_if(surfaces_.begin(), surfaces_.end(), [&](const auto& s) { return s->id() == id; }),
                    surfaces_.end());
    if (selected == id) selected.reset();
}

void Scene::clearSurfaces() {
    surfaces_.clear();
    selected.reset();
}

bool Scene::anyGrowing() const {
    return std::any_of(surfaces_.begin(), surfaces_.end(), [](const auto& s) { return s->growing(); });
}

void Scene::setExplode(float factor) {
    explode_ = factor;
    refreshOffsets();
}

void Scene::refreshOffsets() {
    const glm::vec3 centre = volumeCentre();
    for (auto& surface : surfaces_) surface->setExplode(explode_, centre);
}

void Scene::draw(const render::Renderer& renderer, const render::FrameView& frame,
                 const render::FrameOptions& options) const {
    render::Renderer::beginFrame(frame, options);
    renderer.beginSurfaces(frame, wireframe);
    // Tracked surfaces first: where the exhaustive mesh holds the same triangles, the depth test keeps the first.
    for (const auto& surface : surfaces_) {
        if (surface->tracked()) surface->draw(renderer, selected == surface->id(), colourByGrowth);
    }
    for (const auto& surface : surfaces_) {
        if (!surface->tracked()) surface->draw(renderer, selected == surface->id(), colourByGrowth);
    }
    renderer.endSurfaces(wireframe);
    if (!wireframe && !boundingBox) return;
    renderer.beginLines(frame);
    if (wireframe) {
        renderer.setWireframeMode(true);
        for (const auto& surface : surfaces_) surface->drawWireframe(renderer);
        renderer.setWireframeMode(false);
    }
    if (boundingBox && volume_) renderer.drawBoundingBox();
}

void Scene::drawPick(const render::Renderer& renderer, const render::FrameView& frame,
                     const render::PickTarget& target) const {
    renderer.beginPick(frame, target);
    for (const auto& surface : surfaces_) {
        if (surface->tracked()) surface->drawPick(renderer);
    }
    for (const auto& surface : surfaces_) {
        if (!surface->tracked()) surface->drawPick(renderer);
    }
    renderer.endPick();
}

std::uint64_t Scene::signature(const render::Camera& camera, const render::FrameOptions& options) const {
    Signature signature;
    signature.add(camera.yaw).add(camera.pitch).add(camera.distance).add(camera.target).add(camera.fov);
    signature.add(options.width).add(options.height).add(options.background);
    signature.add(wireframe).add(boundingBox).add(colourByGrowth).add(volume_.get());
    signature.add(selected.has_value()).add(selected.value_or(0));
    for (const auto& surface : surfaces_) {
        const render::SurfaceStyle& style = surface->style();
        signature.add(surface->id()).add(surface->drawnIndexCount());
        signature.add(style.visible).add(style.colour).add(style.offset);
    }
    return signature.value();
}

void Scene::buildUI(ui::PanelState& state) const {
    ui::DataState& data = state.data;
    if (volume_) {
        const Volume& volume = volume_->volume;
        data.loaded = true;
        data.source = volume_->source.text;
        data.sourceName = displayName(volume_->source);
        data.sourceIsFile = volume_->source.kind == VolumeSource::Kind::File;
        data.dims = volume.dims();
        data.scalarType = scalarTypeName(volume.type());
        data.rangeMin = volume_->range[0];
        data.rangeMax = volume_->range[1];
        data.histogram = volume_->histogram;
        data.mappedBytes = volume_->mappedBytes;
        data.valuesRead = volume_->valuesRead;
    }
    state.surfaces.reserve(surfaces_.size());
    for (const auto& surface : surfaces_) surface->buildUI(state);
    state.selected = selected;
    state.view.explode = explode_;
    state.view.wireframe = wireframe;
    state.view.boundingBox = boundingBox;
    state.growth.colourByGrowth = colourByGrowth;
}

// A mapped volume's pages belong to the file (the page cache), not to the
// viewer: the summary reports them as resident bytes instead.
std::size_t Scene::cpuVolumeBytes() const { return volume_ && !volume_->mapped ? volume_->volume.byteSize() : 0; }

std::size_t Scene::cpuMeshBytes() const {
    std::size_t bytes = 0;
    for (const auto& surface : surfaces_) bytes += surface->cpuBytes();
    return bytes;
}

std::size_t Scene::gpuSurfaceBytes() const {
    std::size_t bytes = 0;
    for (const auto& surface : surfaces_) bytes += surface->gpuBytes();
    return bytes;
}

}  // namespace isotrack::viewer
