!> The one thin layer through which LANDYN writes (and, for tests and post-processing, reads) HDF5.
!!
!! Nothing else in LANDYN calls the HDF5 library directly. Every public procedure returns a
!! `status` (type status_t of landyn_status: STAT_OK on success, STAT_FAILED with its message
!! otherwise); it never stops and never prints.
!!
!! ## Error handling
!! - `status` is `type(status_t), intent(out)` everywhere (h5_commit_partial's is intent(inout):
!!   it takes the status of writing the contents). Its message is set only on failure. It names
!!   the operation (the public procedure), the object path inside the file and the file name, e.g.
!!   `h5_read: no dataset '/gear_1/stroke' in file 'run.h5'`.
!! - The HDF5 library's automatic error-stack printing is switched off (h5eset_auto_f(0)) whenever
!!   a file is created or opened, so expected failures (a missing file, a probe of a missing
!!   object) write nothing to stderr.
!! - On failure every HDF5 handle the call opened is released; nothing leaks.
!!
!! ## Shape convention (the output schema depends on it)
!! Arrays are stored in the natural HDF5 layout of Fortran memory: HDF5 lists dimensions in C order
!! (slowest varying first), Fortran's first index varies fastest, so the dimensions appear REVERSED
!! to C/Python readers. A Fortran array a(n1, n2) is read by h5py / h5dump as shape (n2, n1), and
!! a(i, j) is h5py's a[j-1, i-1]. Example: a time series held in Fortran as x(3, nt) (one column
!! per time step) appears in h5py as shape (nt, 3): one row per time step. A(n1, n2, n3) appears
!! as (n3, n2, n1). The readers here undo the reversal: what was written as a(n1, n2) comes back
!! as a(n1, n2). Zero-size arrays are stored as datasets with a zero extent.
!!
!! ## Stored types
!! - real(wp) -> 64-bit IEEE little-endian float (H5T_IEEE_F64LE); integer(ip) -> 32-bit
!!   little-endian signed integer (H5T_STD_I32LE). (landyn_kinds fixes wp = real64, ip = int32.)
!! - logical (scalar) -> integer 0/1 with an extra string attribute "type" = "logical".
!! - character -> fixed-length ASCII strings, null-padded (what h5py and NumPy use for 'S' data),
!!   as long as the longest trimmed value (at least 1). Trailing blanks are not stored; the
!!   readers return values without trailing blanks. Variable-length strings (h5py's default for
!!   Python str) cannot be read by this module.
!! - Every dataset carries a string attribute "units" (mandatory; use '-' for dimensionless,
!!   e.g. 'm', 'N', 'rad', 's') and optionally "description".
!!
!! ## Paths and groups
!! Object paths are absolute ('/gear_1/stroke') or relative to the root group ('gear_1/stroke').
!! Trailing blanks of file names, paths and attribute names are ignored (fixed-length variables
!! may be passed as they are).
!! Writing a dataset creates any missing intermediate groups (like `mkdir -p`). Writing a dataset
!! whose path already exists is an error (results are written once; nothing is overwritten).
!! Writing an attribute that already exists replaces it.
!!
!! ## Library initialisation
!! h5_create / h5_open_read initialise the HDF5 Fortran interface (h5open_f) only when it is not
!! already initialised, which is detected from HDF5's own state (whether the Fortran predefined
!! datatype ids are live), so this module keeps no global state of its own and repeated
!! open/close cycles in one process are fine. h5close_f is never called, and HDF5 registers no
!! exit handler (h5dont_atexit_f): every file is closed explicitly, and after a close that failed
!! (a full disk) HDF5 1.10's exit handler crashed the program instead of letting it report.
!!
!! ## Modules
!! This module only gathers the public interface; the code is in landyn_h5_file (files, groups,
!! rename/delete, files published whole), landyn_h5_write (h5_write, h5_write_attr),
!! landyn_h5_read (h5_read, h5_read_attr) and landyn_h5_base (the handle type, h5_is_open,
!! h5_exists and the shared private plumbing).
module landyn_h5
  use landyn_h5_base, only: h5_file_t, h5_is_open, h5_exists
  use landyn_h5_file, only: h5_create, h5_open_read, h5_close, h5_create_group, rename_file, delete_file, &
    h5_create_partial, h5_commit_partial
  use landyn_h5_write, only: h5_write, h5_write_attr
  use landyn_h5_read, only: h5_read, h5_read_attr
  implicit none
  private

  public :: h5_file_t
  public :: h5_create, h5_open_read, h5_close, h5_is_open
  public :: h5_create_group, h5_exists
  public :: h5_write, h5_write_attr
  public :: h5_read, h5_read_attr
  public :: rename_file, delete_file
  public :: h5_create_partial, h5_commit_partial

end module landyn_h5
