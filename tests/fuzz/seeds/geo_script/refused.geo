SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume("box") = {1};
// SystemCall "x";
If (0)
  SystemCall "touch x";
EndIf
Include "other.geo";
Macro M
  Printf("%g", 1) > "f";
Return
