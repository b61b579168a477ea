"""PPIRay: GPU ray casting of unstructured meshes with partial pre-integration.

Import after (or instead of) the VTK modules you use; the wrapped classes live
in ``ppiray.ppirayFilters``, ``ppiray.ppirayRendering`` and, when PPIRay was
built with CGAL >= 6.1, ``ppiray.ppirayConvexify`` (GPL through CGAL), and are
re-exported here.
"""

# The wrapped modules link against these VTK modules: import them first so that
# their Python types are registered (and the OpenGL2 factory overrides exist).
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolume  # noqa: F401

from .ppirayFilters import *  # noqa: F401,F403
from .ppirayRendering import *  # noqa: F401,F403
try:
    from .ppirayConvexify import *  # noqa: F401,F403
except ImportError:
    pass  # built without CGAL >= 6.1
