"""The cams' figures: the displacement diagram by construction and the profile laid out by
inversion."""
