"""GeoSPH verification report: load result records, fit convergence orders, draw figures, write HTML."""
