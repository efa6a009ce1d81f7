//! How 3D scene errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::{SceneError, MAX_FOCAL_PX, MAX_MESH_VERTICES, MAX_SEGMENTS, MIN_SEGMENTS};

impl Display for SceneError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::OutOfRange => f.write_str("coordinate, size, scale or matrix entry out of range"),
            Self::NonPositive => f.write_str("size, scale or distance is not positive"),
            Self::Segments => write!(
                f,
                "segment count outside {MIN_SEGMENTS}..={MAX_SEGMENTS} or over {MAX_MESH_VERTICES} vertices"
            ),
            Self::Capacity {
                vertices,
                triangles,
            } => write!(
                f,
                "mesh storage too small: {vertices} vertices and {triangles} triangles needed"
            ),
            Self::Scratch { needed } => {
                write!(f, "projection scratch too small: {needed} vertices needed")
            }
            Self::BadIndex => f.write_str("triangle refers to a vertex beyond its mesh"),
            Self::EyeAtTarget => f.write_str("camera eye is at its target"),
            Self::UpParallel => f.write_str("camera up is zero or parallel to the view direction"),
            Self::FieldOfView => write!(
                f,
                "field of view outside (0, 180) degrees or focal length over {MAX_FOCAL_PX} px"
            ),
            Self::ZeroDirection => f.write_str("light direction is zero with a diffuse factor"),
        }
    }
}

impl Error for SceneError {}
