#include "InteractorStyle.h"

#include <vtkObjectFactory.h>

namespace raylab::app {

vtkStandardNewMacro(vtkRaylabInteractorStyle);

void vtkRaylabInteractorStyle::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "Keys: none (RayLab's shortcuts are Qt's)\n";
}

}  // namespace raylab::app
