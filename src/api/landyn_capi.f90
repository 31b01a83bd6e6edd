!> The C API of include/landyn.h: bind(C) functions over landyn_session. A handle is the C address
!! of a heap object that starts with a magic number, checked on every call (a NULL, freed or foreign
!! pointer gives LANDYN_ERR_HANDLE); landyn_free clears the magic number, frees the object and sets
!! the caller's pointer to NULL. Strings from C are NUL-terminated (NULL reads as ''); strings to C
!! are NUL-terminated and truncated to the caller's buffer. No module state: two handles may be used
!! from two threads at once. landyn_version is C (src/api/landyn_capi_version.c).
module landyn_capi
  use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_size_t, c_char, c_null_char, c_int64_t, &
                                         c_associated, c_f_pointer, c_loc, c_null_ptr
  use landyn_kinds, only: wp
  use landyn_strings, only: int_text
  use landyn_session, only: session_t, session_create, session_set_input, session_advance_to, &
                            session_output_index, session_write, api_ok, api_err_input, api_err_handle
  implicit none
  private

  public :: landyn_create, landyn_create_named, landyn_free, landyn_set_input, landyn_advance_to, landyn_time, &
            landyn_output_count, landyn_output_info, landyn_get_outputs, landyn_get_output, landyn_write_result

  !> "LANDYN26" in ASCII: marks a live handle.
  integer(c_int64_t), parameter :: magic_live = int(z'4C414E44594E3236', c_int64_t)

  !> What a handle points to.
  type :: handle_t
    integer(c_int64_t) :: magic = 0_c_int64_t   !! magic_live while the handle is live [-]
    type(session_t) :: s                        !! the simulation [-]
  end type handle_t

  interface
    !> C's strlen.
    pure function c_strlen(p) bind(C, name='strlen') result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value, intent(in) :: p   !! NUL-terminated string [-]
      integer(c_size_t) :: n                !! its length [-]
    end function c_strlen
  end interface

contains

  !> landyn_create: a simulation at t = 0 from deck text and overrides (landyn.h).
  function landyn_create(deck_text, overrides, sim, msg, msg_len) result(rc) bind(C, name='landyn_create')
    type(c_ptr), value, intent(in) :: deck_text    !! const char *: deck text, NULL or "" for the default [-]
    type(c_ptr), value, intent(in) :: overrides    !! const char *: deck text applied on top, NULL or "" [-]
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim **: receives the handle (NULL on failure) [-]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer, may be NULL when msg_len is 0 [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    rc = create_handle(deck_text, c_null_ptr, overrides, sim, msg, msg_len)
  end function landyn_create

  !> landyn_create_named: landyn_create with the deck's name (its file) for messages and provenance.
  function landyn_create_named(deck_text, deck_name, overrides, sim, msg, msg_len) result(rc) &
      bind(C, name='landyn_create_named')
    type(c_ptr), value, intent(in) :: deck_text    !! const char *: deck text, NULL or "" for the default [-]
    type(c_ptr), value, intent(in) :: deck_name    !! const char *: the deck's name, NULL or "" for '(deck text)' [-]
    type(c_ptr), value, intent(in) :: overrides    !! const char *: deck text applied on top, NULL or "" [-]
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim **: receives the handle (NULL on failure) [-]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer, may be NULL when msg_len is 0 [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    rc = create_handle(deck_text, deck_name, overrides, sim, msg, msg_len)
  end function landyn_create_named

  !> The two create calls: a new handle, its session created from the texts.
  function create_handle(deck_text, deck_name, overrides, sim, msg, msg_len) result(rc)
    type(c_ptr), value, intent(in) :: deck_text    !! const char *: deck text, NULL or "" for the default [-]
    type(c_ptr), value, intent(in) :: deck_name    !! const char *: the deck's name, NULL or "" [-]
    type(c_ptr), value, intent(in) :: overrides    !! const char *: deck text applied on top, NULL or "" [-]
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim **: receives the handle (NULL on failure) [-]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer, may be NULL when msg_len is 0 [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(c_ptr), pointer :: out
    type(handle_t), pointer :: h
    character(len=:), allocatable :: text
    integer :: stat
    if (.not. c_associated(sim)) then
      rc = api_err_handle
      call put_text('landyn_create: the handle pointer is NULL', msg, msg_len)
      return
    end if
    call c_f_pointer(sim, out)
    out = c_null_ptr
    allocate (h)
    call session_create(h%s, c_text(deck_text), c_text(overrides), stat, text, deck_name=c_text(deck_name))
    call put_text(text, msg, msg_len)
    rc = int(stat, c_int)
    if (stat /= api_ok) then
      deallocate (h)
      return
    end if
    h%magic = magic_live
    out = c_loc(h)
  end function create_handle

  !> landyn_free: frees the simulation and sets *sim to NULL.
  function landyn_free(sim) result(rc) bind(C, name='landyn_free')
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim **: the caller's handle [-]
    integer(c_int) :: rc                           !! status [-]
    type(c_ptr), pointer :: p
    type(handle_t), pointer :: h
    rc = api_err_handle
    if (.not. c_associated(sim)) return
    call c_f_pointer(sim, p)
    call handle_of(p, h, rc)
    if (rc /= api_ok) return
    h%magic = 0_c_int64_t
    deallocate (h)
    p = c_null_ptr
  end function landyn_free

  !> landyn_set_input: engine force and moment, lander axes, held from now on.
  function landyn_set_input(sim, force, moment, msg, msg_len) result(rc) bind(C, name='landyn_set_input')
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim * [-]
    type(c_ptr), value, intent(in) :: force        !! const double[3]: force at the &engine point, NULL = 0 [N]
    type(c_ptr), value, intent(in) :: moment       !! const double[3]: pure moment, NULL = 0 [N m]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    character(len=:), allocatable :: text
    integer :: stat
    call handle_of(sim, h, rc, 'landyn_set_input', msg, msg_len)
    if (rc /= api_ok) return
    call session_set_input(h%s, c_vector(force), c_vector(moment), stat, text)
    call put_text(text, msg, msg_len)
    rc = int(stat, c_int)
  end function landyn_set_input

  !> landyn_advance_to: advances to time t.
  function landyn_advance_to(sim, t, msg, msg_len) result(rc) bind(C, name='landyn_advance_to')
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim * [-]
    real(c_double), value, intent(in) :: t         !! time to reach [s]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    character(len=:), allocatable :: text
    integer :: stat
    call handle_of(sim, h, rc, 'landyn_advance_to', msg, msg_len)
    if (rc /= api_ok) return
    call session_advance_to(h%s, real(t, wp), stat, text)
    call put_text(text, msg, msg_len)
    rc = int(stat, c_int)
  end function landyn_advance_to

  !> landyn_time: the simulation's time.
  function landyn_time(sim, t) result(rc) bind(C, name='landyn_time')
    type(c_ptr), value, intent(in) :: sim          !! const landyn_sim * [-]
    type(c_ptr), value, intent(in) :: t            !! double *: receives the time [s]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    real(c_double), pointer :: tp
    call handle_of(sim, h, rc, out=t)
    if (rc /= api_ok) return
    call c_f_pointer(t, tp)
    tp = real(h%s%t, c_double)
  end function landyn_time

  !> landyn_output_count: the number of outputs.
  function landyn_output_count(sim, count) result(rc) bind(C, name='landyn_output_count')
    type(c_ptr), value, intent(in) :: sim          !! const landyn_sim * [-]
    type(c_ptr), value, intent(in) :: count        !! int *: receives the count [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    integer(c_int), pointer :: np
    call handle_of(sim, h, rc, out=count)
    if (rc /= api_ok) return
    call c_f_pointer(count, np)
    np = int(size(h%s%outputs), c_int)
  end function landyn_output_count

  !> landyn_output_info: name, unit and meaning of output i (0-based).
  function landyn_output_info(sim, i, name, name_len, unit, unit_len, meaning, meaning_len) result(rc) &
      bind(C, name='landyn_output_info')
    type(c_ptr), value, intent(in) :: sim          !! const landyn_sim * [-]
    integer(c_int), value, intent(in) :: i         !! output index, 0-based [-]
    type(c_ptr), value, intent(in) :: name         !! char *: buffer for the name, may be NULL [-]
    integer(c_size_t), value, intent(in) :: name_len     !! its size in bytes [-]
    type(c_ptr), value, intent(in) :: unit         !! char *: buffer for the unit, may be NULL [-]
    integer(c_size_t), value, intent(in) :: unit_len     !! its size in bytes [-]
    type(c_ptr), value, intent(in) :: meaning      !! char *: buffer for the meaning, may be NULL [-]
    integer(c_size_t), value, intent(in) :: meaning_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    call handle_of(sim, h, rc)
    if (rc /= api_ok) return
    if (i < 0 .or. i >= size(h%s%outputs)) then
      rc = api_err_input
      call put_text('', name, name_len)
      call put_text('', unit, unit_len)
      call put_text('', meaning, meaning_len)
      return
    end if
    associate (o => h%s%outputs(i + 1))
      call put_text(trim(o%name), name, name_len)
      call put_text(trim(o%unit), unit, unit_len)
      call put_text(trim(o%meaning), meaning, meaning_len)
    end associate
  end function landyn_output_info

  !> landyn_get_outputs: all outputs at the current time.
  function landyn_get_outputs(sim, values, n, msg, msg_len) result(rc) bind(C, name='landyn_get_outputs')
    type(c_ptr), value, intent(in) :: sim          !! const landyn_sim * [-]
    type(c_ptr), value, intent(in) :: values       !! double *: receives the values [units of the outputs]
    integer(c_int), value, intent(in) :: n         !! size of values [-]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    real(c_double), pointer :: v(:)
    integer :: m
    call handle_of(sim, h, rc, 'landyn_get_outputs', msg, msg_len)
    if (rc /= api_ok) return
    m = size(h%s%values)
    if (.not. c_associated(values) .or. n < m) then
      rc = api_err_input
      call put_text('landyn_get_outputs: values must hold landyn_output_count = '//int_text(m)//' doubles (n = '// &
                    int_text(int(n))//')', msg, msg_len)
      return
    end if
    call c_f_pointer(values, v, [m])
    v = real(h%s%values, c_double)
    call put_text('', msg, msg_len)
  end function landyn_get_outputs

  !> landyn_get_output: one output by name.
  function landyn_get_output(sim, name, value, msg, msg_len) result(rc) bind(C, name='landyn_get_output')
    type(c_ptr), value, intent(in) :: sim          !! const landyn_sim * [-]
    type(c_ptr), value, intent(in) :: name         !! const char *: output name [-]
    type(c_ptr), value, intent(in) :: value        !! double *: receives the value [unit of the output]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    real(c_double), pointer :: vp
    character(len=:), allocatable :: key, closest
    integer :: k
    call handle_of(sim, h, rc, 'landyn_get_output', msg, msg_len, out=value, out_name='value')
    if (rc /= api_ok) return
    key = c_text(name)
    call session_output_index(h%s, key, k, closest)
    if (k == 0) then
      rc = api_err_input
      call put_text('landyn_get_output: unknown output '''//key//'''; did you mean '''//closest//'''?', msg, msg_len)
      return
    end if
    call c_f_pointer(value, vp)
    vp = real(h%s%values(k), c_double)
    call put_text('', msg, msg_len)
  end function landyn_get_output

  !> landyn_write_result: the result file of what was run so far.
  function landyn_write_result(sim, path, msg, msg_len) result(rc) bind(C, name='landyn_write_result')
    type(c_ptr), value, intent(in) :: sim          !! landyn_sim * [-]
    type(c_ptr), value, intent(in) :: path         !! const char *: file name [-]
    type(c_ptr), value, intent(in) :: msg          !! char *: message buffer [-]
    integer(c_size_t), value, intent(in) :: msg_len  !! its size in bytes [-]
    integer(c_int) :: rc                           !! status [-]
    type(handle_t), pointer :: h
    character(len=:), allocatable :: text
    integer :: stat
    call handle_of(sim, h, rc, 'landyn_write_result', msg, msg_len)
    if (rc /= api_ok) return
    call session_write(h%s, c_text(path), stat, text)
    call put_text(text, msg, msg_len)
    rc = int(stat, c_int)
  end function landyn_write_result

  ! ---------------------------------------------------------------- helpers

  !> The handle behind a C pointer: api_ok and h associated when it is live, else api_err_handle;
  !! with `out`, the pointer a call writes its result through, api_err_input (h associated) when
  !! that is NULL.
  subroutine handle_of(p, h, rc, caller, msg, msg_len, out, out_name)
    type(c_ptr), intent(in) :: p                   !! the caller's pointer [-]
    type(handle_t), pointer, intent(out) :: h      !! the handle, null unless live [-]
    integer(c_int), intent(out) :: rc              !! api_ok, api_err_handle or api_err_input [-]
    character(len=*), intent(in), optional :: caller       !! the C function, for the message [-]
    type(c_ptr), intent(in), optional :: msg               !! char *: message buffer (with caller) [-]
    integer(c_size_t), intent(in), optional :: msg_len     !! its size in bytes [-]
    type(c_ptr), intent(in), optional :: out               !! the pointer the call writes its result through [-]
    character(len=*), intent(in), optional :: out_name     !! its name, for the message (with caller) [-]
    logical :: say
    say = present(caller) .and. present(msg) .and. present(msg_len)
    h => null()
    rc = api_err_handle
    if (c_associated(p)) then
      call c_f_pointer(p, h)
      if (h%magic == magic_live) then
        rc = api_ok
        if (present(out)) then
          if (c_associated(out)) return
          rc = api_err_input
          if (say .and. present(out_name)) call put_text(caller//': '//out_name//' is NULL', msg, msg_len)
        end if
        return
      end if
      h => null()
    end if
    if (say) call put_text(caller//': not a live LANDYN handle', msg, msg_len)
  end subroutine handle_of

  !> A NUL-terminated C string as Fortran text ('' for NULL).
  function c_text(p) result(text)
    type(c_ptr), intent(in) :: p                   !! const char * [-]
    character(len=:), allocatable :: text          !! its characters [-]
    character(kind=c_char), pointer :: chars(:)
    integer :: n, i
    text = ''
    if (.not. c_associated(p)) return
    n = int(c_strlen(p))
    if (n == 0) return
    call c_f_pointer(p, chars, [n])
    deallocate (text)
    allocate (character(len=n) :: text)
    do i = 1, n
      text(i:i) = chars(i)
    end do
  end function c_text

  !> Three doubles from C (zeros for NULL).
  function c_vector(p) result(v)
    type(c_ptr), intent(in) :: p                   !! const double[3] [any]
    real(wp) :: v(3)                               !! the values [any]
    real(c_double), pointer :: x(:)
    v = 0.0_wp
    if (.not. c_associated(p)) return
    call c_f_pointer(p, x, [3])
    v = real(x, wp)
  end function c_vector

  !> Copies text into a C buffer of buf_len bytes: truncated to buf_len - 1 characters and
  !! NUL-terminated; nothing for a NULL buffer or buf_len 0.
  subroutine put_text(text, buf, buf_len)
    character(len=*), intent(in) :: text           !! text [-]
    type(c_ptr), intent(in) :: buf                 !! char * [-]
    integer(c_size_t), intent(in) :: buf_len       !! its size in bytes [-]
    character(kind=c_char), pointer :: chars(:)
    integer :: m, i
    if (.not. c_associated(buf) .or. buf_len < 1) return
    call c_f_pointer(buf, chars, [buf_len])
    m = int(min(int(len(text), c_size_t), buf_len - 1))
    do i = 1, m
      chars(i) = text(i:i)
    end do
    chars(m + 1) = c_null_char
  end subroutine put_text

end module landyn_capi
