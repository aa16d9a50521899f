"""A picture of a quarter model's part at the end of its run, seen from
below (the punch side of a drawn part is inside), mirrored to the full part
and coloured by thinning: the picture of the pan in doc/user-guide.md 4.4.
    xvfb-run -a /usr/bin/python3 benchmarks/part_picture.py RUN_DIR OUT.png"""
import glob
import os
import sys

import vtk


def main():
    run, out = sys.argv[1], sys.argv[2]
    last = sorted(glob.glob(os.path.join(run, "solution_*.pvtu")))[-1]
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(last)
    parts = vtk.vtkAppendFilter()
    for sx, sy in ((1, 1), (-1, 1), (1, -1), (-1, -1)):
        mirror = vtk.vtkTransform()
        mirror.Scale(sx, sy, 1)
        moved = vtk.vtkTransformFilter()
        moved.SetTransform(mirror)
        moved.SetInputConnection(reader.GetOutputPort())
        parts.AddInputConnection(moved.GetOutputPort())
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(parts.GetOutputPort())
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0)
    lut.Build()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("thinning_percent")
    mapper.SetScalarRange(-5, 25)
    mapper.SetLookupTable(lut)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1, 1, 1)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("thinning (%)")
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0, 0, 0)
    bar.SetWidth(0.08)
    bar.SetHeight(0.6)
    bar.SetPosition(0.9, 0.2)
    renderer.AddActor2D(bar)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, -10)
    camera.SetPosition(-120, -200, -160)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.6)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(900, 600)
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()


main()
