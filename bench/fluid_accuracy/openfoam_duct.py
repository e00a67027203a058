#!/usr/bin/env python3
"""The sphere held in the sliding duct (`fluid_accuracy --duct`) solved by OpenFOAM.

An independent solution of the same steady problem on a body-fitted mesh: blockMesh for the
duct, snappyHexMesh cutting and snapping the sphere (a searchableSphere, refined towards its
surface), simpleFoam (steady, laminar, second-order linear convection). Prints the drag over
Stokes's 3 pi mu U d. Units: d = 1, U = 1, rho = 1, nu = 1 / Re.

Needs OpenFOAM (Debian: apt-get install openfoam); benchmark only, never a dependency.
Example: bench/fluid_accuracy/openfoam_duct.py --cells-per-diameter 6 --levels 2 3
"""
import argparse
import math
import pathlib
import subprocess
import tempfile

WIDTH, UPSTREAM, DOWNSTREAM = 20.0 / 3, 5.0, 11.0

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def write(case, path, cls, obj, body):
    target = case / path
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(HEADER.format(cls=cls, obj=obj) + body)


def block_mesh(n):
    across, along = round(WIDTH * n), round((UPSTREAM + DOWNSTREAM) * n)
    w, length = WIDTH, along / n
    return f"""convertToMeters 1;
vertices ((0 0 0) ({w} 0 0) ({w} {w} 0) (0 {w} 0) (0 0 {length}) ({w} 0 {length}) ({w} {w} {length}) (0 {w} {length}));
blocks (hex (0 1 2 3 4 5 6 7) ({across} {across} {along}) simpleGrading (1 1 1));
boundary (
  inlet {{ type patch; faces ((0 3 2 1)); }}
  outlet {{ type patch; faces ((4 5 6 7)); }}
  walls {{ type wall; faces ((0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7)); }}
);
"""


def snappy(level):
    c = WIDTH / 2
    return f"""castellatedMesh true; snap true; addLayers false;
geometry {{
  sphere {{ type searchableSphere; centre ({c} {c} {UPSTREAM}); radius 0.5; }}
  near {{ type searchableSphere; centre ({c} {c} {UPSTREAM}); radius 1.5; }}
}}
castellatedMeshControls {{
  maxLocalCells 10000000; maxGlobalCells 20000000; minRefinementCells 0; maxLoadUnbalance 0.1;
  nCellsBetweenLevels 3; features ();
  refinementSurfaces {{ sphere {{ level ({level} {level}); patchInfo {{ type wall; }} }} }}
  resolveFeatureAngle 30;
  refinementRegions {{ near {{ mode inside; levels ((1e15 {max(level - 1, 0)})); }} }}
  locationInMesh (0.31 0.27 0.53); allowFreeStandingZoneFaces true;
}}
snapControls {{ nSmoothPatch 3; tolerance 2.0; nSolveIter 100; nRelaxIter 5; nFeatureSnapIter 10;
  implicitFeatureSnap false; explicitFeatureSnap false; multiRegionFeatureSnap false; }}
addLayersControls {{ relativeSizes true; layers {{}}; expansionRatio 1; finalLayerThickness 0.3; minThickness 0.1;
  nGrow 0; featureAngle 60; nRelaxIter 3; nSmoothSurfaceNormals 1; nSmoothNormals 3; nSmoothThickness 10;
  maxFaceThicknessRatio 0.5; maxThicknessToMedialRatio 0.3; minMedialAxisAngle 90; nBufferCellsNoExtrude 0;
  nLayerIter 50; }}
meshQualityControls {{ maxNonOrtho 65; maxBoundarySkewness 20; maxInternalSkewness 4; maxConcave 80;
  minVol 1e-13; minTetQuality 1e-15; minArea -1; minTwist 0.02; minDeterminant 0.001; minFaceWeight 0.05;
  minVolRatio 0.01; minTriangleTwist -1; nSmoothScale 4; errorReduction 0.75; }}
mergeTolerance 1e-6;
"""


def case_files(case, n, level, reynolds, iterations):
    write(case, "system/blockMeshDict", "dictionary", "blockMeshDict", block_mesh(n))
    write(case, "system/snappyHexMeshDict", "dictionary", "snappyHexMeshDict", snappy(level))
    write(case, "system/controlDict", "dictionary", "controlDict", f"""application simpleFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime {iterations}; deltaT 1;
writeControl timeStep; writeInterval {iterations}; purgeWrite 0; writeFormat ascii; writePrecision 8;
writeCompression off; timeFormat general; timePrecision 6; runTimeModifiable false;
functions {{
  forces {{ type forces; libs (forces); writeControl timeStep; writeInterval 1; patches (sphere);
    rho rhoInf; rhoInf 1; CofR ({WIDTH / 2} {WIDTH / 2} {UPSTREAM}); log false; }}
}}
""")
    write(case, "system/fvSchemes", "dictionary", "fvSchemes", """ddtSchemes { default steadyState; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) bounded Gauss linear; div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
    write(case, "system/fvSolution", "dictionary", "fvSolution", """solvers {
  p { solver GAMG; smoother GaussSeidel; tolerance 1e-10; relTol 0.05; }
  U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-12; relTol 0.1; }
}
SIMPLE { nNonOrthogonalCorrectors 1; consistent yes; residualControl { p 1e-8; U 1e-9; } }
relaxationFactors { equations { U 0.9; ".*" 0.9; } }
""")
    write(case, "constant/transportProperties", "dictionary", "transportProperties",
          f"transportModel Newtonian; nu {1.0 / reynolds:.12g};\n")
    write(case, "constant/turbulenceProperties", "dictionary", "turbulenceProperties", "simulationType laminar;\n")
    write(case, "0/U", "volVectorField", "U", """dimensions [0 1 -1 0 0 0 0]; internalField uniform (0 0 1);
boundaryField {
  inlet { type fixedValue; value uniform (0 0 1); }
  outlet { type zeroGradient; }
  walls { type fixedValue; value uniform (0 0 1); }
  sphere { type noSlip; }
}
""")
    write(case, "0/p", "volScalarField", "p", """dimensions [0 2 -2 0 0 0 0]; internalField uniform 0;
boundaryField {
  inlet { type zeroGradient; }
  outlet { type fixedValue; value uniform 0; }
  walls { type zeroGradient; }
  sphere { type zeroGradient; }
}
""")


def run(case, bashrc, command):
    script = f"source '{bashrc}' >/dev/null 2>&1; cd '{case}' && {command}"
    log = case / ("log." + command.split()[0])
    with open(log, "w") as out:
        subprocess.run(["bash", "-c", script], stdout=out, stderr=subprocess.STDOUT, check=True)
    return log


def drag(case):
    files = sorted(case.glob("postProcessing/forces/*/force.dat"))
    last = [l for l in files[-1].read_text().splitlines() if l and not l.startswith("#")][-1]
    numbers = [float(x) for x in last.replace("(", " ").replace(")", " ").split()]
    return numbers[0], numbers[3]  # iteration, total force along z


def cells(case):
    for line in (case / "log.checkMesh").read_text().splitlines():
        if line.strip().startswith("cells:"):
            return int(line.split()[1])
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cells-per-diameter", type=int, default=6, help="the background mesh (a multiple of 3)")
    parser.add_argument("--levels", type=int, nargs="+", default=[2, 3], help="snappyHexMesh's levels at the sphere")
    parser.add_argument("--reynolds", type=float, default=1.5)
    parser.add_argument("--iterations", type=int, default=3000)
    parser.add_argument("--bashrc", default="/usr/share/openfoam/etc/bashrc")
    parser.add_argument("--keep", help="build the cases under this directory and keep them")
    args = parser.parse_args()
    root = pathlib.Path(args.keep or tempfile.mkdtemp(prefix="openfoam_duct."))
    print(f"sphere held in the sliding duct, OpenFOAM simpleFoam, Re {args.reynolds:g}")
    print(f"{'d/h at sphere':>13} {'cells':>9} {'iterations':>10} {'F/(3 pi mu U d)':>16}")
    for level in args.levels:
        case = root / f"level{level}"
        case_files(case, args.cells_per_diameter, level, args.reynolds, args.iterations)
        run(case, args.bashrc, "blockMesh")
        run(case, args.bashrc, "snappyHexMesh -overwrite")
        run(case, args.bashrc, "checkMesh")
        run(case, args.bashrc, "simpleFoam")
        iteration, fz = drag(case)
        nu = 1.0 / args.reynolds
        print(f"{args.cells_per_diameter * 2 ** level:13d} {cells(case):9d} {int(iteration):10d} "
              f"{fz / (3 * math.pi * nu):16.5f}")


if __name__ == "__main__":
    main()
