//! Legacy-VTK particle snapshots (ParaView opens them directly; glyph the
//! points by `radius` to see spheres).

use super::runner::Scene;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

pub fn write_snapshot(scene: &Scene, path: &Path) -> io::Result<()> {
    let mut f = BufWriter::new(File::create(path)?);
    let n = scene.spheres.len();
    writeln!(f, "# vtk DataFile Version 3.0")?;
    writeln!(f, "granbond scene step {} time {:e}", scene.step, scene.time())?;
    writeln!(f, "ASCII\nDATASET POLYDATA\nPOINTS {n} double")?;
    for s in &scene.spheres {
        writeln!(f, "{:e} {:e} {:e}", s.body.x.x, s.body.x.y, s.body.x.z)?;
    }
    writeln!(f, "VERTICES {} {}", n, 2 * n)?;
    for i in 0..n {
        writeln!(f, "1 {i}")?;
    }
    writeln!(f, "POINT_DATA {n}\nSCALARS radius double 1\nLOOKUP_TABLE default")?;
    for s in &scene.spheres {
        writeln!(f, "{:e}", s.radius)?;
    }
    writeln!(f, "VECTORS velocity double")?;
    for s in &scene.spheres {
        writeln!(f, "{:e} {:e} {:e}", s.body.v.x, s.body.v.y, s.body.v.z)?;
    }
    f.flush()
}
