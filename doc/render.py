# SPDX-License-Identifier: BSD-3-Clause
"""The README's pictures, rendered by ParaView's pvbatch (doc/render.sh runs it with the
inputs it made in WORK): pvbatch doc/render.py WORK OUT_DIR"""
import os
import sys

from paraview.simple import (Text, GetActiveViewOrCreate, Hide, LegacyVTKReader, OpenDataFile, ResetCamera,
                             SaveScreenshot, Show, Threshold, Transform)

WORK, OUT = sys.argv[1], sys.argv[2]
SURFACE = [0.78, 0.82, 0.9]
EDGES = [0.25, 0.27, 0.35]
RIDGES = [0.85, 0.1, 0.1]


def new_view(size):
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = size
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    for source in list(view.Representations):
        source.Visibility = 0
    return view


def shifted(source, dx=0.0, dy=0.0):
    moved = Transform(Input=source)
    moved.Transform.Translate = [dx, dy, 0.0]
    return moved


def show_mesh(source, view, edges=True):
    shown = Show(source, view)
    shown.SetRepresentationType("Surface With Edges" if edges else "Surface")
    shown.ColorArrayName = ["POINTS", ""]
    shown.DiffuseColor = SURFACE
    shown.EdgeColor = EDGES
    return shown


def show_ridges(source, view):
    lines = Threshold(Input=source, Scalars=["CELLS", "ridge"])
    if hasattr(lines, "LowerThreshold"):
        lines.LowerThreshold, lines.UpperThreshold = 0.5, 1.5
    else:
        lines.ThresholdRange = [0.5, 1.5]
    shown = Show(lines, view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.AmbientColor = shown.DiffuseColor = RIDGES
    shown.LineWidth = 3
    return shown


def label(view, text, where):
    shown = Show(Text(Text=text), view)
    shown.WindowLocation = "Any Location"
    shown.Position = where
    shown.Color = [0.1, 0.1, 0.1]
    shown.FontSize = 14


def look(view, direction, up, zoom=1.0, focal=None):
    ResetCamera(view)
    camera = view.GetActiveCamera()
    f = list(focal) if focal else list(camera.GetFocalPoint())
    distance = camera.GetDistance()
    view.CameraFocalPoint = f
    view.CameraPosition = [f[i] + distance * direction[i] for i in range(3)]
    view.CameraViewUp = up
    ResetCamera(view) if focal is None else None
    view.GetActiveCamera().Dolly(zoom)


def save(view, name, size):
    SaveScreenshot(os.path.join(OUT, name), view, ImageResolution=size)
    print("wrote", os.path.join(OUT, name))


def part():
    size = [1400, 560]
    view = new_view(size)
    generated = LegacyVTKReader(FileNames=[os.path.join(WORK, "demo", "part.vtk")])
    remeshed = LegacyVTKReader(FileNames=[os.path.join(WORK, "demo", "remeshed.vtk")])
    for source in (shifted(generated, dx=-2.6), shifted(remeshed, dx=2.6)):
        show_mesh(source, view)
        show_ridges(source, view)
    label(view, "as generated (CAD-like)", [0.2, 0.9])
    label(view, "remeshed at edge length 0.08: ridges in red", [0.58, 0.9])
    look(view, [0.35, -0.75, 0.75], [0, 0, 1], zoom=1.6)
    save(view, "part.png", size)

    # A ridge band: the chamfer's edges and the hole's rim, close up, on the remeshed part.
    size = [900, 600]
    view = new_view(size)
    show_mesh(remeshed, view)
    show_ridges(remeshed, view)
    look(view, [0.35, -0.75, 0.75], [0, 0, 1], zoom=3.0)
    save(view, "ridge-band.png", size)


def enright():
    size = [1200, 600]
    view = new_view(size)
    half = OpenDataFile(os.path.join(WORK, "enright", "t1.5.obj"))
    end = OpenDataFile(os.path.join(WORK, "enright", "t3.obj"))
    show_mesh(half, view, edges=False)
    show_mesh(shifted(end, dx=0.75), view, edges=False)
    label(view, "Enright flow, t = 1.5 (the sheet at its thinnest)", [0.08, 0.9])
    label(view, "t = 3: back to a sphere", [0.62, 0.9])
    look(view, [0.2, -1.0, 0.45], [0, 0, 1], zoom=1.4)
    save(view, "enright.png", size)


def two_drops():
    size = [1500, 450]
    view = new_view(size)
    show_mesh(OpenDataFile(os.path.join(WORK, "two_drops.obj")), view)
    label(view, "before", [0.17, 0.85])
    label(view, "the call that merges them", [0.4, 0.85])
    label(view, "six sfa_adapt calls later", [0.7, 0.85])
    look(view, [0.2, -1.0, 0.35], [0, 0, 1], zoom=2.1)
    save(view, "two-drops.png", size)


part()
enright()
two_drops()
