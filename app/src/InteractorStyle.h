#pragma once

#include <vtkInteractorStyleTrackballCamera.h>

namespace raylab::app {

/**
 * \brief The 3D view's mouse handling: VTK's trackball camera (drag rotates, wheel zooms,
 * as in the original course program), with none of VTK's own keys. VTK's default keys
 * (w: wireframe, s: surfaces, e/q: quit, j/t, 3: stereo, p: pick, f: fly to, r: reset)
 * would do undocumented things in a classroom; only RayLab's documented shortcuts act.
 */
class vtkRaylabInteractorStyle : public vtkInteractorStyleTrackballCamera {
 public:
  static vtkRaylabInteractorStyle* New();
  // clang-format off
  vtkTypeMacro(vtkRaylabInteractorStyle, vtkInteractorStyleTrackballCamera)
      // clang-format on
      void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Keys go to Qt's shortcuts, never to VTK's.
  void OnChar() override {}
  void OnKeyPress() override {}
  void OnKeyRelease() override {}

 protected:
  vtkRaylabInteractorStyle() = default;
  ~vtkRaylabInteractorStyle() override = default;

 private:
  vtkRaylabInteractorStyle(const vtkRaylabInteractorStyle&) = delete;
  void operator=(const vtkRaylabInteractorStyle&) = delete;
};

}  // namespace raylab::app
