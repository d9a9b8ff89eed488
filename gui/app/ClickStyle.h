#pragma once

// Trackball camera control that also reports clicks (a press and release
// without a drag) and the end of each camera move.

#include <vtkInteractorStyleTrackballCamera.h>

#include <cstdlib>
#include <functional>

namespace viewpipe::gui {

class ClickStyle : public vtkInteractorStyleTrackballCamera {
public:
    static ClickStyle* New();
    vtkTypeMacro(ClickStyle, vtkInteractorStyleTrackballCamera)

    std::function<void(int x, int y)> onClick;
    std::function<void()> onCameraMoved;

    void OnLeftButtonDown() override
    {
        GetInteractor()->GetEventPosition(pressX_, pressY_);
        vtkInteractorStyleTrackballCamera::OnLeftButtonDown();
    }

    void OnLeftButtonUp() override
    {
        vtkInteractorStyleTrackballCamera::OnLeftButtonUp();
        int x, y;
        GetInteractor()->GetEventPosition(x, y);
        if (std::abs(x - pressX_) + std::abs(y - pressY_) < 3) {
            if (onClick)
                onClick(x, y);
        } else {
            cameraMoved();
        }
    }

    // Each calls its base by name: through a member pointer the call would be virtual, and come back here.
    // The wheel zooms through StartDolly and EndDolly too.
    void EndDolly() override
    {
        vtkInteractorStyleTrackballCamera::EndDolly();
        cameraMoved();
    }
    void EndPan() override
    {
        vtkInteractorStyleTrackballCamera::EndPan();
        cameraMoved();
    }
    void EndSpin() override
    {
        vtkInteractorStyleTrackballCamera::EndSpin();
        cameraMoved();
    }

private:
    void cameraMoved()
    {
        if (onCameraMoved)
            onCameraMoved();
    }
    int pressX_ = 0, pressY_ = 0;
};

inline ClickStyle* ClickStyle::New()
{
    auto* style = new ClickStyle;
    style->InitializeObjectBase();
    return style;
}

} // namespace viewpipe::gui
