"""Exposure: EV and EV100, light levels, equivalents, ND filters, bellows, plans, stops, metering, reciprocity, times."""
