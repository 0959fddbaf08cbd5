% NLvib's three-oscillator example (examples/three_oscillators_jenkins.toml) run by NLvib itself,
% for the cross-check in docs/elements.md and tests/data/nlvib/three_oscillators/README.md.
% NLvib (GPL-3, https://github.com/maltekrack/NLvib) is not part of hbtrack: point NLVIB_SRC at
% its SRC folder. Writes, in the current folder:
%   nlvib_points.csv      NLvib's branch in states.csv's layout (omega, x1_h0, ..., x3_s7) and
%                         NLvib's own residual max|R| at each point;
%   hbtrack_in_nlvib.csv  with HBTRACK_POINTS=FILE (hbtrack's points in the same layout, as
%                         scripts/reference/nlvib_cross_check.py writes them): omega and max|R|
%                         of NLvib's residual at each of hbtrack's points.
% Run: NLVIB_SRC=/path/to/NLvib/SRC octave-cli scripts/reference/nlvib_three_oscillators.m
src = getenv('NLVIB_SRC');
if isempty(src), error('NLVIB_SRC: set it to NLvib''s SRC folder'); end
addpath(src); addpath(fullfile(src, 'MechanicalSystems'));

% The example's system (hbtrack's case file gives the same numbers).
jenkins = @(w) struct('type', 'elasticDryFriction', 'stiffness', 20, 'friction_limit_force', 1, ...
                      'ishysteretic', true, 'force_direction', w);
elements = {jenkins([1; 0; 0]), jenkins([-1; 1; 0]), ...
            struct('type', 'cubicSpring', 'stiffness', 1, 'force_direction', [0; 1; 0]), ...
            struct('type', 'cubicSpring', 'stiffness', 1, 'force_direction', [0; -1; 1]), ...
            struct('type', 'unilateralSpring', 'stiffness', 1, 'gap', 0.25, 'force_direction', [0; 0; 1])};
chain = ChainOfOscillators([1 1 1], 0.02 * [1 1 1 1], [1 1 1 1], elements, [0; 1; 0]);
H = 7; N = 1024; n = 3;
residual = @(X) HB_residual(X, chain, H, N, 'frf');

% NLvib's start: the linear response with the sticking Jenkins springs added, at omega = 0.5.
stuck = 20 * ([1; 0; 0] * [1 0 0] + [-1; 1; 0] * [-1 1 0]);
Q1 = (-0.25 * chain.M + 0.5i * chain.D + chain.K + stuck) \ chain.Fex1;
x0 = zeros((2 * H + 1) * n, 1);
x0(n + (1:2 * n)) = [real(Q1); -imag(Q1)];
omega_end = str2double(getenv('NLVIB_OMEGA_END'));  % a shorter run to try the script
if isnan(omega_end), omega_end = 2; end
tic;
X = solve_and_continue(x0, residual, 0.5, omega_end, 0.005);
printf('%d points in %.1f s\n', columns(X), toc);

% NLvib's own residual at each point (Octave's fsolve may accept a point it did not converge).
own = zeros(columns(X), 1);
for i = 1:columns(X), own(i) = max(abs(residual(X(:, i)))); end
names = {'omega'};
for h = 0:H
  parts = {'c', 's'}; if h == 0, parts = {'h'}; end
  for p = 1:numel(parts)
    for d = 1:n
      names{end + 1} = sprintf('x%d_%s%d', d, parts{p}, h);
    end
  end
end
names{end + 1} = 'nlvib_residual';
file = fopen('nlvib_points.csv', 'w'); fprintf(file, '%s\n', strjoin(names, ',')); fclose(file);
dlmwrite('nlvib_points.csv', [X(end, :)' X(1:end - 1, :)' own], '-append', 'precision', 17);

points = getenv('HBTRACK_POINTS');
if ~isempty(points)
  P = dlmread(points, ',', 1, 0);  % header row: omega, x1_h0, ...
  r = zeros(rows(P), 1);
  for i = 1:rows(P), r(i) = max(abs(residual([P(i, 2:end)'; P(i, 1)]))); end
  file = fopen('hbtrack_in_nlvib.csv', 'w'); fprintf(file, 'omega,nlvib_residual\n'); fclose(file);
  dlmwrite('hbtrack_in_nlvib.csv', [P(:, 1) r], '-append', 'precision', 17);
end
