#pragma once
// Reference geometry in the scene: imported .iv graphs (scene/iv_import.h) drawn greyed and
// translucent over one material that overrides theirs, and unpickable, so that a press on them
// goes through to the planes behind (strokes land on the active plane as without them) and no
// pick ever returns a path into them (they are not entities and cannot be edited).
#include <memory>
#include <vector>

class SoSeparator;
class SoSwitch;

namespace sculptline::scene {

class ReferenceLayer {
public:
    ReferenceLayer();
    ~ReferenceLayer();
    ReferenceLayer(const ReferenceLayer&) = delete;
    ReferenceLayer& operator=(const ReferenceLayer&) = delete;

    /// The layer's graph: SoSeparator "References" { SoPickStyle UNPICKABLE, SoMaterial (override),
    /// SoSwitch { one graph per reference } }.
    SoSeparator* root() const { return root_; }
    /// Shows exactly these graphs, in this order (null entries are skipped: a missing file).
    void setGraphs(const std::vector<std::shared_ptr<SoSeparator>>& graphs);
    int count() const;
    /// View > References: hides or shows every reference (a view setting, not an edit).
    void setVisible(bool visible);
    bool visible() const;

private:
    SoSeparator* root_ = nullptr;  ///< ref()ed
    SoSwitch* switch_ = nullptr;
    std::vector<std::shared_ptr<SoSeparator>> graphs_;
};

}  // namespace sculptline::scene
