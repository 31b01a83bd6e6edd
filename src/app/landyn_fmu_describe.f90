!> The landyn_fmu_describe program writes the two generated files of the FMI 2.0 co-simulation FMU
!! (docs/api.md, "FMU"): `modelDescription.xml` and `landyn_fmu_vars.c`, the FMU's table of
!! variables (value reference -> role, type, deck group and deck item, start value), from one walk
!! of the input registry (the parameters, starts from the resolved default deck), the engine inputs
!! and the C API's output list (api_output_list for max_gears gears of max_struts struts).
!!
!!   landyn_fmu_describe OUT_DIR
!!
!! The guid is derived from the content (a hash of the description written with an empty guid),
!! so it changes exactly when the description does. Exit status 0, or 1 on a usage or file error.
program landyn_fmu_describe
  use, intrinsic :: iso_fortran_env, only: error_unit, int64
  use landyn_kinds, only: max_gears, max_struts
  use landyn_config, only: landyn_input_t, default_input, is_set
  use landyn_errors, only: input_errors_t
  use landyn_input, only: resolve_input
  use landyn_input_registry, only: input_vars, group_names, k_real, k_int, k_logical, k_string
  use landyn_input_access, only: input_value_t, access_var
  use landyn_input_format, only: fmt_real, fmt_angle
  use landyn_strings, only: int_text
  use landyn_version, only: landyn_version_string, landyn_git_revision
  use landyn_api_outputs, only: api_output_t, api_output_list
  use landyn_cli, only: get_arg
  implicit none

  !> One FMU variable: its value reference is its index - 1.
  type :: fmu_var_t
    character(len=:), allocatable :: name        !! FMI variable name (structured naming) [-]
    character(len=:), allocatable :: ftype       !! 'Real', 'Integer', 'Boolean' or 'String' [-]
    character(len=:), allocatable :: role        !! C role: PARAMETER, DECK_FILE, RESULT_FILE, INPUT, OUTPUT [-]
    character(len=:), allocatable :: group       !! parameters: deck group [-]
    character(len=:), allocatable :: item        !! parameters: deck item, e.g. 'velocity(3)'; outputs: name [-]
    character(len=:), allocatable :: start       !! start value as text ('' for outputs) [deck unit]
    character(len=:), allocatable :: lo          !! min ('' for none) [deck unit]
    character(len=:), allocatable :: hi          !! max ('' for none) [deck unit]
    character(len=:), allocatable :: unit        !! unit ('' for none) [-]
    character(len=:), allocatable :: description !! one-line meaning [-]
    integer :: component = 0                     !! inputs: 0..5 (force x, y, z, moment x, y, z) [-]
  end type fmu_var_t

  type(fmu_var_t), allocatable :: vars(:)
  character(len=:), allocatable :: out_dir, xml, guid
  integer :: n_args, stat

  n_args = command_argument_count()
  if (n_args /= 1) then
    write (error_unit, '(a)') 'usage: landyn_fmu_describe OUT_DIR'
    stop 1
  end if
  out_dir = get_arg(1)
  allocate (vars(0))
  call add_parameters(vars)
  call add_inputs(vars)
  call add_outputs(vars)
  xml = model_description(vars, '')
  guid = guid_of(xml)
  xml = model_description(vars, guid)
  call write_text(out_dir//'/modelDescription.xml', xml, stat)
  if (stat == 0) call write_text(out_dir//'/landyn_fmu_vars.c', c_table(vars, guid), stat)
  if (stat /= 0) then
    write (error_unit, '(a)') 'landyn_fmu_describe: cannot write into '//out_dir
    stop 1
  end if

contains

  !> Append one variable.
  subroutine push(list, v)
    type(fmu_var_t), allocatable, intent(inout) :: list(:)  !! variables [-]
    type(fmu_var_t), intent(in) :: v                        !! variable to append [-]
    list = [list, v]
  end subroutine push

  !> A variable with the given name, type and role, every other text empty.
  function new_var(name, ftype, role) result(v)
    character(len=*), intent(in) :: name    !! FMI name [-]
    character(len=*), intent(in) :: ftype   !! FMI type [-]
    character(len=*), intent(in) :: role    !! C role [-]
    type(fmu_var_t) :: v                    !! the variable [-]
    v%name = name
    v%ftype = ftype
    v%role = role
    v%group = ''
    v%item = ''
    v%start = ''
    v%lo = ''
    v%hi = ''
    v%unit = ''
    v%description = ''
  end function new_var

  !> The parameters: every element of every registry variable that the resolved default deck sets
  !! (deck units: angles in degrees), then deck_file and result_file.
  subroutine add_parameters(list)
    type(fmu_var_t), allocatable, intent(inout) :: list(:)  !! variables [-]
    type(landyn_input_t) :: inp
    type(input_errors_t) :: errors
    type(input_value_t) :: val
    type(fmu_var_t) :: v
    integer :: iv, i, j, n1, ncol, nrow, k
    character(len=:), allocatable :: base, gname
    inp = default_input()
    call resolve_input(inp, errors)
    do iv = 1, size(input_vars)
      call access_var(inp, iv, val, .false.)
      gname = trim(group_names(input_vars(iv)%group))
      base = trim(input_vars(iv)%name)
      n1 = input_vars(iv)%n1
      nrow = max(1, n1)
      ncol = max(1, input_vars(iv)%n2)
      do j = 1, ncol
        do i = 1, nrow
          k = (j - 1)*nrow + i
          if (input_vars(iv)%kind == k_real) then
            if (.not. is_set(val%r(k))) cycle
          end if
          v = new_var(gname//'.'//base//subscript(n1, input_vars(iv)%n2, i, j, '[', ']', ','), &
                      fmi_type(input_vars(iv)%kind), 'PARAMETER')
          v%group = gname
          v%item = base//subscript(n1, input_vars(iv)%n2, i, j, '(', ')', ', ')
          v%start = start_text(iv, val, k)
          call set_bounds(v, iv)
          v%description = trim(input_vars(iv)%meaning)
          call push(list, v)
        end do
      end do
    end do
    v = new_var('deck_file', 'String', 'DECK_FILE')
    v%description = 'deck the parameters apply on top of ("" = the defaults)'
    call push(list, v)
    v = new_var('result_file', 'String', 'RESULT_FILE')
    v%description = 'HDF5 result file written at fmi2Terminate ("" = none)'
    call push(list, v)
  end subroutine add_parameters

  !> '' for a scalar, '<l>i<r>' for a vector, '<l>i<sep>j<r>' for a matrix.
  pure function subscript(n1, n2, i, j, l, r, sep) result(s)
    integer, intent(in) :: n1, n2            !! extents (0: none) [-]
    integer, intent(in) :: i, j              !! element [-]
    character(len=*), intent(in) :: l, r     !! brackets [-]
    character(len=*), intent(in) :: sep      !! separator of two indices [-]
    character(len=:), allocatable :: s       !! subscript [-]
    s = ''
    if (n1 > 0 .and. n2 > 0) then
      s = l//int_text(i)//sep//int_text(j)//r
    else if (n1 > 0) then
      s = l//int_text(i)//r
    end if
  end function subscript

  !> The FMI type of a registry storage class.
  pure function fmi_type(kind) result(s)
    integer, intent(in) :: kind              !! k_real, k_int, k_logical or k_string [-]
    character(len=:), allocatable :: s       !! FMI type name [-]
    select case (kind)
    case (k_int)
      s = 'Integer'
    case (k_logical)
      s = 'Boolean'
    case (k_string)
      s = 'String'
    case default
      s = 'Real'
    end select
  end function fmi_type

  !> Start value of element k of entry iv as FMI text (reals: the shortest text that reads back
  !! exactly, angles in degrees).
  function start_text(iv, val, k) result(s)
    integer, intent(in) :: iv                   !! registry entry [-]
    type(input_value_t), intent(in) :: val      !! its resolved default value [storage unit]
    integer, intent(in) :: k                    !! element (column-major) [-]
    character(len=:), allocatable :: s          !! start [deck unit]
    select case (input_vars(iv)%kind)
    case (k_int)
      s = int_text(val%i)
    case (k_logical)
      s = 'false'
      if (val%l) s = 'true'
    case (k_string)
      s = trim(val%s)
    case default
      if (input_vars(iv)%angle) then
        s = fmt_angle(val%r(k))
      else
        s = fmt_real(val%r(k))
      end if
    end select
  end function start_text

  !> min/max and unit of a parameter from its registry entry (bounds of reals and integers only).
  subroutine set_bounds(v, iv)
    type(fmu_var_t), intent(inout) :: v      !! parameter [-]
    integer, intent(in) :: iv                !! registry entry [-]
    if (input_vars(iv)%kind == k_real .or. input_vars(iv)%kind == k_int) then
      if (len_trim(input_vars(iv)%lo_op) > 0) v%lo = trim(input_vars(iv)%lo)
      if (len_trim(input_vars(iv)%hi_op) > 0) v%hi = trim(input_vars(iv)%hi)
    end if
    if (input_vars(iv)%kind == k_real) v%unit = unit_name(input_vars(iv)%unit)
  end subroutine set_bounds

  !> The unit as FMI names it: '' for none and for dimensionless '-'.
  pure function unit_name(u) result(s)
    character(len=*), intent(in) :: u        !! registry or output unit [-]
    character(len=:), allocatable :: s       !! FMI unit name [-]
    s = trim(u)
    if (s == '-') s = ''
  end function unit_name

  !> The inputs: engine force and moment, lander frame, added to the deck's &engine thrust.
  subroutine add_inputs(list)
    type(fmu_var_t), allocatable, intent(inout) :: list(:)  !! variables [-]
    character(len=1), parameter :: axes(3) = ['x', 'y', 'z']
    character(len=1) :: a
    type(fmu_var_t) :: v
    integer :: k
    do k = 1, 6
      a = axes(mod(k - 1, 3) + 1)
      if (k <= 3) then
        v = new_var('engine.force.'//a, 'Real', 'INPUT')
        v%unit = 'N'
        v%description = 'engine force along lander '//a//', at the &engine point, added to the deck''s thrust'
      else
        v = new_var('engine.moment.'//a, 'Real', 'INPUT')
        v%unit = 'N m'
        v%description = 'engine moment about lander '//a//', added to the deck''s thrust'
      end if
      v%start = '0.0'
      v%component = k - 1
      call push(list, v)
    end do
  end subroutine add_inputs

  !> The outputs of the C API for max_gears gears of max_struts struts (0 where the deck has fewer).
  subroutine add_outputs(list)
    type(fmu_var_t), allocatable, intent(inout) :: list(:)  !! variables [-]
    type(api_output_t), allocatable :: outs(:)
    type(fmu_var_t) :: v
    integer :: k
    allocate (outs(0))
    outs = api_output_list(max_gears, [(max_struts, k = 1, max_gears)])
    do k = 1, size(outs)
      v = new_var(trim(outs(k)%name), 'Real', 'OUTPUT')
      v%item = trim(outs(k)%name)
      v%unit = unit_name(outs(k)%unit)
      v%description = trim(outs(k)%meaning)
      call push(list, v)
    end do
  end subroutine add_outputs

  !> The whole modelDescription.xml.
  function model_description(list, guid) result(x)
    type(fmu_var_t), intent(in) :: list(:)   !! variables [-]
    character(len=*), intent(in) :: guid     !! guid ('' while hashing) [-]
    character(len=:), allocatable :: x       !! XML text [-]
    character(len=*), parameter :: nl = new_line('a')
    integer :: k
    x = '<?xml version="1.0" encoding="UTF-8"?>'//nl// &
        '<fmiModelDescription fmiVersion="2.0" modelName="landyn" guid="'//guid//'"'//nl// &
        '  description="LANDYN: touchdown dynamics of a legged planetary lander"'//nl// &
        '  generationTool="LANDYN '//landyn_version_string//' ('//xml_escape(landyn_git_revision)//')"'//nl// &
        '  variableNamingConvention="structured" numberOfEventIndicators="0">'//nl// &
        '  <CoSimulation modelIdentifier="landyn" canHandleVariableCommunicationStepSize="true"'//nl// &
        '    canGetAndSetFMUstate="false" canSerializeFMUstate="false"'// &
        ' providesDirectionalDerivative="false"/>'//nl
    x = x//unit_definitions(list)
    x = x//'  <LogCategories>'//nl//'    <Category name="logStatusError" description="errors"/>'//nl// &
        '    <Category name="logStatusDiscard" description="the run ended before the step''s end"/>'//nl// &
        '  </LogCategories>'//nl
    x = x//experiment()
    x = x//'  <ModelVariables>'//nl
    do k = 1, size(list)
      x = x//scalar_variable(list(k), k - 1)
    end do
    x = x//'  </ModelVariables>'//nl//'  <ModelStructure>'//nl
    x = x//unknowns('Outputs', list)//unknowns('InitialUnknowns', list)
    x = x//'  </ModelStructure>'//nl//'</fmiModelDescription>'//nl
  end function model_description

  !> <DefaultExperiment>: the default deck's t_end, steps of its &output interval.
  function experiment() result(x)
    character(len=:), allocatable :: x       !! XML text [-]
    type(landyn_input_t) :: inp
    inp = default_input()
    x = '  <DefaultExperiment startTime="0.0" stopTime="'//fmt_real(inp%simulation%t_end)//'" stepSize="'// &
        fmt_real(inp%output%interval)//'"/>'//new_line('a')
  end function experiment

  !> <UnitDefinitions> with every unit used, in order of first use.
  function unit_definitions(list) result(x)
    type(fmu_var_t), intent(in) :: list(:)   !! variables [-]
    character(len=:), allocatable :: x       !! XML text [-]
    integer :: k, m
    logical :: seen
    x = '  <UnitDefinitions>'//new_line('a')
    do k = 1, size(list)
      if (len(list(k)%unit) == 0) cycle
      seen = .false.
      do m = 1, k - 1
        if (list(m)%unit == list(k)%unit) seen = .true.
      end do
      if (.not. seen) x = x//'    <Unit name="'//xml_escape(list(k)%unit)//'"/>'//new_line('a')
    end do
    x = x//'  </UnitDefinitions>'//new_line('a')
  end function unit_definitions

  !> One <ScalarVariable>.
  function scalar_variable(v, vr) result(x)
    type(fmu_var_t), intent(in) :: v         !! variable [-]
    integer, intent(in) :: vr                !! value reference [-]
    character(len=:), allocatable :: x       !! XML text [-]
    character(len=:), allocatable :: causality, variability, attrs
    select case (v%role)
    case ('INPUT')
      causality = 'input'
      variability = 'continuous'
    case ('OUTPUT')
      causality = 'output'
      variability = 'continuous'
    case default
      causality = 'parameter'
      variability = 'fixed'
    end select
    x = '    <ScalarVariable name="'//xml_escape(v%name)//'" valueReference="'//int_text(vr)// &
        '" causality="'//causality//'" variability="'//variability//'"'
    if (causality == 'parameter') x = x//' initial="exact"'
    x = x//new_line('a')//'      description="'//xml_escape(v%description)//'">'//new_line('a')
    attrs = ''
    if (v%role /= 'OUTPUT') attrs = ' start="'//xml_escape(v%start)//'"'
    if (len(v%unit) > 0) attrs = attrs//' unit="'//xml_escape(v%unit)//'"'
    if (len(v%lo) > 0) attrs = attrs//' min="'//v%lo//'"'
    if (len(v%hi) > 0) attrs = attrs//' max="'//v%hi//'"'
    x = x//'      <'//v%ftype//attrs//'/>'//new_line('a')//'    </ScalarVariable>'//new_line('a')
  end function scalar_variable

  !> <Outputs> or <InitialUnknowns>: every output, by its 1-based index in ModelVariables.
  function unknowns(tag, list) result(x)
    character(len=*), intent(in) :: tag      !! element name [-]
    type(fmu_var_t), intent(in) :: list(:)   !! variables [-]
    character(len=:), allocatable :: x       !! XML text [-]
    integer :: k
    x = '    <'//tag//'>'//new_line('a')
    do k = 1, size(list)
      if (list(k)%role == 'OUTPUT') x = x//'      <Unknown index="'//int_text(k)//'"/>'//new_line('a')
    end do
    x = x//'    </'//tag//'>'//new_line('a')
  end function unknowns

  !> Text with &, <, > and " escaped for XML.
  pure function xml_escape(s) result(t)
    character(len=*), intent(in) :: s        !! text [-]
    character(len=:), allocatable :: t       !! escaped text [-]
    integer :: i
    t = ''
    do i = 1, len(s)
      select case (s(i:i))
      case ('&')
        t = t//'&amp;'
      case ('<')
        t = t//'&lt;'
      case ('>')
        t = t//'&gt;'
      case ('"')
        t = t//'&quot;'
      case default
        t = t//s(i:i)
      end select
    end do
  end function xml_escape

  !> Text as a C string literal.
  pure function c_string(s) result(t)
    character(len=*), intent(in) :: s        !! text [-]
    character(len=:), allocatable :: t       !! "..." with \ and " escaped [-]
    integer :: i
    t = '"'
    do i = 1, len(s)
      if (s(i:i) == '\' .or. s(i:i) == '"') t = t//'\'
      t = t//s(i:i)
    end do
    t = t//'"'
  end function c_string

  !> The generated C table (src/api/fmu/landyn_fmu_vars.h declares it).
  function c_table(list, guid) result(x)
    type(fmu_var_t), intent(in) :: list(:)   !! variables [-]
    character(len=*), intent(in) :: guid     !! guid [-]
    character(len=:), allocatable :: x       !! C text [-]
    character(len=*), parameter :: nl = new_line('a')
    character(len=:), allocatable :: rs, is, ss
    integer :: k
    x = '/* Generated by landyn_fmu_describe (src/app/landyn_fmu_describe.f90): do not edit. */'//nl// &
        '#include "landyn_fmu_vars.h"'//nl//nl// &
        'const char landyn_fmu_guid[] = '//c_string(guid)//';'//nl// &
        'const int landyn_fmu_n_vars = '//int_text(size(list))//';'//nl//nl// &
        '/* role, type, name, group, item, real start, integer/boolean start or input component, string start */'//nl// &
        'const landyn_fmu_var landyn_fmu_vars[] = {'//nl
    do k = 1, size(list)
      rs = '0.0'
      ss = ''
      is = int_text(list(k)%component)
      select case (list(k)%ftype)
      case ('Real')
        if (len(list(k)%start) > 0) rs = list(k)%start
      case ('Integer')
        is = list(k)%start
      case ('Boolean')
        is = '0'
        if (list(k)%start == 'true') is = '1'
      case ('String')
        ss = list(k)%start
      end select
      x = x//'  {LANDYN_FMU_'//list(k)%role//', LANDYN_FMU_'//upper(list(k)%ftype)//', '//c_string(list(k)%name)// &
          ', '//c_string(list(k)%group)//', '//c_string(list(k)%item)//','//nl// &
          '   '//rs//', '//is//', '//c_string(ss)//'},'//nl
    end do
    x = x//'};'//nl
  end function c_table

  !> Upper case of an ASCII word.
  pure function upper(s) result(t)
    character(len=*), intent(in) :: s        !! word [-]
    character(len=:), allocatable :: t       !! upper case [-]
    integer :: i
    t = s
    do i = 1, len(t)
      if (t(i:i) >= 'a' .and. t(i:i) <= 'z') t(i:i) = achar(iachar(t(i:i)) - 32)
    end do
  end function upper

  !> A guid from the text: four 32-bit FNV-1a hashes with different offset bases, as
  !! {8-4-4-4-12} hexadecimal digits.
  pure function guid_of(text) result(g)
    character(len=*), intent(in) :: text     !! text to hash [-]
    character(len=:), allocatable :: g       !! guid [-]
    integer(int64), parameter :: two32 = 4294967296_int64, prime = 16777619_int64
    integer(int64) :: h(4)
    character(len=8) :: hex(4)
    integer :: i, k
    h = [2166136261_int64, 1088903141_int64, 3735928559_int64, 2654435769_int64]
    do i = 1, len(text)
      do k = 1, 4
        h(k) = mod(ieor(h(k), int(iachar(text(i:i)), int64))*prime, two32)
      end do
    end do
    do k = 1, 4
      write (hex(k), '(z8.8)') h(k)
    end do
    g = '{'//hex(1)//'-'//hex(2)(1:4)//'-'//hex(2)(5:8)//'-'//hex(3)(1:4)//'-'//hex(3)(5:8)//hex(4)//'}'
  end function guid_of

  !> Write text to a file as it is (bytes, no record structure).
  subroutine write_text(path, text, stat)
    character(len=*), intent(in) :: path     !! file [-]
    character(len=*), intent(in) :: text     !! content [-]
    integer, intent(out) :: stat             !! 0 when written [-]
    integer :: u
    open (newunit=u, file=path, access='stream', form='unformatted', status='replace', action='write', iostat=stat)
    if (stat /= 0) return
    write (u, iostat=stat) text
    close (u)
  end subroutine write_text

end program landyn_fmu_describe
