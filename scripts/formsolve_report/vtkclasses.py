"""The VTK classes the report uses, imported from their own modules:
`import vtk` loads all of VTK's modules (0.35 s on the 2-core machine of
doc/performance.md, against 0.15 s for these). Used as
`from . import vtkclasses as vtk`, so that the code reads vtk.vtkActor()
as with VTK's own module; imported only where VTK is used (the --render
subprocess, a --travel without its sheet CSV)."""
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkBox, vtkCellArray, vtkPlane, vtkPolyData, vtkUnstructuredGrid
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import (vtkAppendFilter, vtkAppendPolyData, vtkCutter, vtkFeatureEdges,
                                       vtkPolyDataNormals)
from vtkmodules.vtkFiltersGeneral import vtkClipDataSet, vtkReflectionFilter, vtkTransformFilter
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter, vtkGeometryFilter
from vtkmodules.vtkFiltersModeling import vtkLinearExtrusionFilter, vtkRotationalExtrusionFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkLightKit, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)
# Modules not used by name: importing them registers the implementations
# behind the classes above (the OpenGL render window and mappers, the fonts
# of the text); without them the window draws nothing.
from vtkmodules import vtkRenderingFreeType, vtkRenderingOpenGL2

__all__ = ["vtkActor", "vtkAppendFilter", "vtkAppendPolyData", "vtkBox", "vtkCellArray", "vtkClipDataSet", "vtkCutter",
           "vtkDataSetMapper",
           "vtkDataSetSurfaceFilter", "vtkDoubleArray", "vtkFeatureEdges", "vtkGeometryFilter", "vtkLightKit",
           "vtkLinearExtrusionFilter",
           "vtkLookupTable", "vtkPlane", "vtkPNGWriter", "vtkPoints", "vtkPolyData", "vtkPolyDataMapper",
           "vtkPolyDataNormals", "vtkReflectionFilter", "vtkRenderWindow", "vtkRenderer",
           "vtkRotationalExtrusionFilter", "vtkScalarBarActor", "vtkSphereSource", "vtkTextActor",
           "vtkTransform", "vtkTransformFilter", "vtkUnstructuredGrid", "vtkWindowToImageFilter",
           "vtkXMLPUnstructuredGridReader", "vtkXMLUnstructuredGridReader",
           "vtkRenderingFreeType", "vtkRenderingOpenGL2"]
