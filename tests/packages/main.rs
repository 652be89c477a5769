//! The integration tests that need Debian packages, in one binary: the window (an X server,
//! Xvfb), the survey of POV-Ray's sample scenes (povray-examples, povray-includes,
//! fonts-povray) and the render farm on a one-node Slurm cluster (slurmctld, slurmd,
//! slurm-client, munge). Where a package is missing its tests are `#[ignore]`d with the reason, so
//! `cargo test --release` lists them as ignored; `.ci/run` installs the packages and runs
//! `cargo test --release --test packages -- --ignored`, where a missing package fails.

mod slurm;
mod survey;
mod window;
