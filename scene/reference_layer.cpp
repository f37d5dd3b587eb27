#include "scene/reference_layer.h"

#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

namespace sculptline::scene {
namespace {

/// A light neutral grey that reads as "not part of the model" against the dark background and the
/// warm curves and cool surfaces of the model.
const SbColor kReferenceGrey(0.62f, 0.62f, 0.62f);
/// Translucent enough to see the planes and curves behind it, opaque enough to trace its outline.
constexpr float kReferenceTransparency = 0.55f;

}  // namespace

ReferenceLayer::ReferenceLayer()
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("References");
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    root_->addChild(pick);
    // One colour for everything below: the file's own materials are overridden.
    auto* material = new SoMaterial;
    material->diffuseColor = kReferenceGrey;
    material->ambientColor = SbColor(0.2f, 0.2f, 0.2f);
    material->specularColor = SbColor(0.0f, 0.0f, 0.0f);
    material->emissiveColor = SbColor(0.08f, 0.08f, 0.08f);
    material->transparency = kReferenceTransparency;
    material->setOverride(TRUE);
    root_->addChild(material);
    auto* binding = new SoMaterialBinding;
    binding->value = SoMaterialBinding::OVERALL;
    binding->setOverride(TRUE);
    root_->addChild(binding);
    switch_ = new SoSwitch;
    switch_->whichChild = SO_SWITCH_ALL;
    root_->addChild(switch_);
}

ReferenceLayer::~ReferenceLayer()
{
    switch_->removeAllChildren();
    root_->unref();
}

void ReferenceLayer::setGraphs(const std::vector<std::shared_ptr<SoSeparator>>& graphs)
{
    switch_->removeAllChildren();
    graphs_.clear();
    for (const auto& g : graphs) {
        if (!g) continue;
        graphs_.push_back(g);
        switch_->addChild(g.get());
    }
}

int ReferenceLayer::count() const { return switch_->getNumChildren(); }

void ReferenceLayer::setVisible(bool visible) { switch_->whichChild = visible ? SO_SWITCH_ALL : SO_SWITCH_NONE; }

bool ReferenceLayer::visible() const { return switch_->whichChild.getValue() == SO_SWITCH_ALL; }

}  // namespace sculptline::scene
