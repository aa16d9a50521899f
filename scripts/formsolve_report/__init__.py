"""formsolve-report DIR: the run report of a formsolve output folder.

Writes DIR/report/ (DIR/report-<T>mm/ with --travel T):
  report.md, report.html   how the run ended (a split first), the key numbers,
                           the pictures; report.html embeds them (one file)
  force-travel.png         punch, blank-holder and die force; the ironed
                           wall's pressure below when the wall is ironed
  thickness.png            thickness along the section (0, 45, 90 degrees in 3-D)
  fld.png                  the columns' strains in formsolve's FLD zones
                           (sheet.csv's zone column), the FLC and its band
  damage.png               the fracture criteria against punch travel
  earing.png / draw-in.png 3-D: cup height per angle once drawn through,
                           else the flange draw-in per angle
  thickness-change.png,    the whole part (mirrored or revolved) rendered
  penetration.png          with VTK offscreen, the tools faint

Needs Debian's python3-matplotlib; python3-vtk9 (and an X server or
xvfb-run) only for the two rendered pictures and for --travel without a
sheet_<T>mm.csv. A missing module is named and only what needs it is left
out. Exit status 0 when report.md was written, 1 when DIR is no formsolve
output folder, 2 for a wrong command line.

The modules, one concept each:
  cli       the command line and the order of the work (main)
  readers   run-summary.txt and the CSV files as text, numbers, travels
  zones     formsolve's FLD zones (names, colours, keys)
  rundata   Run: what the report reads of an output folder, cut at --travel
  vtu       VTU files: reading them, sheet.csv's rows rebuilt from one
  split     the split: when, where, which measures were met
  history   quantities of history.csv shared by tables and plots
  outcome   how the run ended, in sentences
  tables    the key numbers and the solver checks
  plots     the matplotlib pictures
  pictures  which pictures the report has, in order, with captions
  mesh      deal.II's VTU cells as a clean VTK surface
  scene     the part made whole (revolved or mirrored), the camera direction
  window    the scene drawn offscreen, coloured by a field, into a PNG
  render    the VTK pictures, made in a subprocess (formsolve-report --render)
            that runs while this process makes the plots
  vtkclasses  the VTK classes used, imported from their own modules
  page      report.md and report.html
  timing    where the time goes (FORMSOLVE_REPORT_TIMES=FILE,
            benchmarks/report_time.sh)

scripts/formsolve-report is the launcher: it finds this package next to
itself (source and build tree) or in <prefix>/share/formsolve/python/."""
