// Carries each vertex's pass index to the fragments: across a strip between pass k and k + 1
// it runs from k to k + 1, so the passes themselves are where it is a whole number.
// Declarations: replaces //VTK::PositionVC::Dec. Implementation: //VTK::PositionVC::Impl.
//DECLARATIONS
in float passCoord;
out float passCoordVSOutput;
//IMPLEMENTATION
passCoordVSOutput = passCoord;
