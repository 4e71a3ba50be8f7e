% Example `pathref conform` adapter in GNU Octave (>= 7, for jsondecode/jsonencode): answers
% grid.coord (the corrected form only) and metrics.length over the pathref-conform v1 protocol
% (spec/conform.md). NOT run by CI (Debian's octave is ~130 packages); the manual check is
%
%   apt-get install octave-cli
%   build/pathref conform --exec "octave-cli --no-gui -q tools/conform/example_adapter.m" \
%       --rules 'grid.coord,metrics.length' golden/        # exit 0: every vector passes or skips
%   PATHREF_PLANTED_BUG=1 build/pathref conform --exec "octave-cli --no-gui -q tools/conform/example_adapter.m" \
%       --rules 'grid.coord,metrics.length' golden/        # exit 1: metrics.length fails
%
% With PATHREF_PLANTED_BUG=1, metrics.length forgets the last step of the path (the planted bug).
1;

function out = coord(in)
  W = in.width; H = in.height; i = in.index;
  if W < 1 || H < 1 || i < 0 || i >= W * H || any(fix([W H i]) ~= [W H i])
    error('pathref:DomainError', 'W, H >= 1 and 0 <= index < W*H');
  end
  out = struct('centre', [mod(i, W) + 0.5, floor(i / W) + 0.5]);
end

function out = path_length(in, planted)
  p = in.path;
  if isempty(p)
    error('pathref:DomainError', 'the path is empty');
  end
  if any(abs(p(:)) > 2^25)
    error('pathref:DomainError', 'a coordinate exceeds 2^25');
  end
  n = rows(p);
  if planted
    n = max(1, n - 1);   % the planted bug: the last step is forgotten
  end
  total = 0;
  for k = 2:n
    d = p(k, :) - p(k - 1, :);
    if all(d == 0)
      error('pathref:DomainError', 'two consecutive nodes are equal');
    end
    total = total + sqrt(d(1)^2 + d(2)^2);   % exact integer sum, one correctly rounded sqrt
  end
  out = struct('length', total);
end

planted = strcmp(getenv('PATHREF_PLANTED_BUG'), '1');
while true
  line = fgetl(stdin);
  if ~ischar(line)
    break;
  end
  if isempty(strtrim(line))
    continue;
  end
  req = jsondecode(line);
  if isfield(req, 'protocol')
    ans_ = struct('protocol', 'pathref-conform', 'version', 1);
    ans_.rules = {'grid.coord', 'metrics.length'};
  else
    ans_ = struct('id', req.id);
    try
      if strcmp(req.rule, 'grid.coord')
        if isfield(req.input, 'form') && ~strcmp(req.input.form, 'corrected')
          ans_.skip = 'only the corrected form of Eq. 1 is implemented';
        else
          ans_.output = coord(req.input);
        end
      elseif strcmp(req.rule, 'metrics.length')
        ans_.output = path_length(req.input, planted);
      else
        ans_.skip = 'rule not implemented';
      end
    catch err
      if strcmp(err.identifier, 'pathref:DomainError')
        ans_.error = 'DomainError';
      else
        ans_.error = 'UsageError';
      end
      ans_.message = err.message;
    end
  end
  printf('%s\n', jsonencode(ans_));
  fflush(stdout);
end
