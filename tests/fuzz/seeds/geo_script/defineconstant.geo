DefineConstant[ a = {1, Min 0, Max 2, Name "P/a"}, b = 2, s = {"x", Name "P/s"}, c = {2 * 0.5, Name "P/c"} ];
DefineConstant[ = e, {, ] ;
