#pragma once
// What the user asked to extract, and the worker that makes it so. The viewer
// says what it wants (source, isovalue, table, method) and submits it with
// its surfaces' seeds and own isovalues; take() hands back the newest finished result
// that is still wanted. A request for another source, method or table makes
// every result of an older request void (the worker cancels the work); one for
// another isovalue or other seeds does not, so results keep arriving while the
// isovalue is dragged. It also keeps what is shown: the isovalue of the last
// result applied and how many results were applied.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "viewer/extraction_worker.h"

namespace isotrack::viewer {

class ExtractionController {
public:
    ExtractionController(int threads, std::uint64_t memoryBudget) : worker_(threads, memoryBudget) {}

    // ---- what is wanted ----
    const VolumeSource& source() const { return source_; }
    void setSource(VolumeSource source);                       // also back to the source's default isovalue
    const std::optional<double>& iso() const { return iso_; }  // nullopt: the source's default
    void setIso(double iso) { iso_ = iso; }
    TableKind table() const { return table_; }
    void setTable(TableKind table) { table_ = table; }
    ui::Method method() const { return method_; }
    void setMethod(ui::Method method) { method_ = method; }
    double minPersistence() const { return minPersistence_; }  // method tree: 0, or the simplification's
    void setMinPersistence(double persistence) { minPersistence_ = persistence; }
    // The user agreed that `method` may read the whole source (a volume over
    // the memory budget); asked once per source and method.
    void confirm(ui::Method method) { confirmed_.insert(method); }
    bool confirmed(ui::Method method) const { return confirmed_.count(method) != 0; }

    // Sends what is wanted, with the scene's surfaces (their seeds and own
    // isovalues); `onlyOwnIsovalues`: only the surfaces with their own isovalue changed.
    void submit(std::vector<PreviousSurface> surfaces, bool onlyOwnIsovalues = false);
    // The newest finished result that is not void, if one is waiting.
    std::optional<ExtractionResult> take();

    // ---- what is shown ----
    void applied(const ExtractionResult& result);  // the viewer shows this result now
    const std::optional<double>& shownIso() const { return shownIso_; }
    std::size_t appliedCount() const { return applied_; }
    double lastMs() const { return lastMs_; }

    WorkerProgress progress() const { return worker_.progress(); }
    bool busy() const { return worker_.busy(); }
    std::size_t cancelledCount() const { return worker_.cancelledCount(); }

private:
    ExtractionWorker worker_;
    VolumeSource source_;
    std::optional<double> iso_;
    TableKind table_ = TableKind::Consistent;
    ui::Method method_ = ui::Method::All;
    double minPersistence_ = 0.0;
    std::set<ui::Method> confirmed_;  // for source_

    std::uint64_t generation_ = 0;
    std::uint64_t epoch_ = 0;  // results of requests before this one are void
    std::optional<ExtractionRequest> lastRequest_;

    std::optional<double> shownIso_;
    std::size_t applied_ = 0;
    double lastMs_ = 0.0;
};

}  // namespace isotrack::viewer
