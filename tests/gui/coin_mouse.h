#pragma once
// Simulated mouse events through Coin's SoHandleEventAction on a graph seen from an orthographic
// camera: the path a mouse takes in the viewer, without a window (the dragger and binding tests).
#include "scene/eigen_coin.h"

#include <Inventor/SbTime.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoHandleEventAction.h>
#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <initializer_list>

namespace sculptline::guitest {

class CoinMouse {
public:
    static constexpr short kWidth = 400, kHeight = 400;

    /// A scene of `content` under a camera that views it all (looking down -Z).
    explicit CoinMouse(std::initializer_list<SoNode*> content) : scene_(new SoSeparator), camera_(new SoOrthographicCamera)
    {
        scene_->ref();
        scene_->addChild(camera_);
        for (SoNode* node : content) scene_->addChild(node);
        camera_->viewAll(scene_, viewport());
    }
    ~CoinMouse() { scene_->unref(); }
    CoinMouse(const CoinMouse&) = delete;
    CoinMouse& operator=(const CoinMouse&) = delete;

    SbViewportRegion viewport() const { return SbViewportRegion(kWidth, kHeight); }

    /// Pixel (origin bottom-left, as in Coin events) of a world point.
    SbVec2s pixelOf(const Eigen::Vector3d& p) const
    {
        SbVec3f ndc;
        camera_->getViewVolume(1.0f).projectToScreen(scene::toSb(p), ndc);
        return SbVec2s(static_cast<short>(ndc[0] * kWidth), static_cast<short>(ndc[1] * kHeight));
    }

    void press(const SbVec2s& pixel) { button(pixel, SoButtonEvent::DOWN); }
    void release(const SbVec2s& pixel) { button(pixel, SoButtonEvent::UP); }
    void move(const SbVec2s& pixel)
    {
        SoLocation2Event e;
        send(e, pixel);
    }

private:
    void button(const SbVec2s& pixel, SoButtonEvent::State state)
    {
        SoMouseButtonEvent e;
        e.setButton(SoMouseButtonEvent::BUTTON1);
        e.setState(state);
        send(e, pixel);
    }
    void send(SoEvent& event, const SbVec2s& pixel)
    {
        event.setPosition(pixel);
        event.setTime(SbTime::getTimeOfDay());
        SoHandleEventAction action(viewport());
        action.setEvent(&event);
        action.apply(scene_);
    }

    SoSeparator* scene_;
    SoOrthographicCamera* camera_;
};

}  // namespace sculptline::guitest
