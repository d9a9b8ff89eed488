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
        } else if (onCameraMoved) {
            onCameraMoved();
        }
    }

    void EndDolly() override { finish(&vtkInteractorStyleTrackballCamera::EndDolly); }
    void EndPan() override { finish(&vtkInteractorStyleTrackballCamera::EndPan); }
    void EndSpin() override { finish(&vtkInteractorStyleTrackballCamera::EndSpin); }
    void OnMouseWheelForward() override
    {
        vtkInteractorStyleTrackballCamera::OnMouseWheelForward();
        if (onCameraMoved)
            onCameraMoved();
    }
    void OnMouseWheelBackward() override
    {
        vtkInteractorStyleTrackballCamera::OnMouseWheelBackward();
        if (onCameraMoved)
            onCameraMoved();
    }

private:
    void finish(void (vtkInteractorStyleTrackballCamera::*end)())
    {
        (this->*end)();
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
