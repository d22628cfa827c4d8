"""The sheet: GOST frame and title block, the views' layout and the fit of scale factors."""
