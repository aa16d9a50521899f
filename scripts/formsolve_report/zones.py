"""formsolve's FLD zones, indexed by the zone number of sheet.csv,
history.csv and the VTU field safety_zone (material/forming_limit.h). The
report only reads them: the program classifies."""

ZONES = [("safe", "#2ca02c"), ("insufficient stretch", "#17becf"),
         ("wrinkling tendency", "#9467bd"), ("compression", "#7f7f7f"),
         ("severe thinning", "#e377c2"), ("risk of crack", "#ff7f0e"),
         ("crack", "#d62728"), ("fracture", "#000000")]


def zone_key(name):
    """The zone's name as in run-summary.txt's and history.csv's columns_<key>."""
    return name.replace(" ", "_")
